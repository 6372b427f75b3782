//! Reading a scene: the TOML parsed with its spans, every key checked against its range, errors that name the file, the line and the key.

use super::*;

impl Scene {
    /// The embedded default scene.
    pub fn default_scene() -> Self {
        Self::from_toml_str(DEFAULT_SCENE_TOML, DEFAULT_SCENE_NAME).expect("the embedded default scene is valid")
    }

    /// Reads and checks a scene file.
    ///
    /// # Errors
    /// [`SceneError`] if the file cannot be read, is not UTF-8 (with the line of the first bad
    /// byte), is not valid TOML, has an unknown key or a value of the wrong type, or a value out of
    /// range.
    pub fn load(path: &Path) -> Result<Self, SceneError> {
        let name = path.display().to_string();
        let bytes = std::fs::read(path).map_err(|e| SceneError {
            file: name.clone(),
            line: None,
            message: format!("cannot read the scene file: {e}"),
        })?;
        let text = match String::from_utf8(bytes) {
            Ok(t) => t,
            Err(e) => {
                let at = e.utf8_error().valid_up_to();
                let bytes = e.as_bytes();
                let line = bytes[..at].iter().filter(|&&b| b == b'\n').count() + 1;
                return Err(SceneError {
                    file: name,
                    line: Some(line),
                    message: format!(
                        "the scene file is not UTF-8 text: byte {at} (0x{:02x}) is not valid UTF-8 (save the file as UTF-8)",
                        bytes[at]
                    ),
                });
            }
        };
        Self::from_toml_str(&text, &name)
    }

    /// The scene as a scene file (TOML) that [`Scene::from_toml_str`] reads back as the same
    /// scene; what `brine view` saves.
    ///
    /// # Errors
    /// [`SceneError`] (naming `file`) if the scene breaks a rule of the scene files: a value out
    /// of its range, keys that exclude each other.
    pub fn to_toml(&self, file: &str) -> Result<String, SceneError> {
        let text = toml::to_string(self).map_err(|e| SceneError {
            file: file.to_owned(),
            line: None,
            message: e.to_string(),
        })?;
        // What is written is what is read back: the checks of a loaded file, and the same scene.
        let back = Self::from_toml_str(&text, file)?;
        if back != (Self { elapsed_s: 0.0, ..self.clone() }) {
            return Err(SceneError {
                file: file.to_owned(),
                line: None,
                message: "the scene does not survive being written as TOML (a value TOML cannot hold?)".into(),
            });
        }
        Ok(text)
    }

    /// Parses and checks a scene from TOML text; `file` names it in messages.
    ///
    /// Every key is checked against the key table ([`keys::KEYS`]: type, range, array length)
    /// on the parsed document, then the keys that constrain each other. Messages carry the line
    /// of the key, whether it is written under a header, dotted, quoted or in an inline table.
    ///
    /// # Errors
    /// See [`Scene::load`].
    pub fn from_toml_str(text: &str, file: &str) -> Result<Self, SceneError> {
        // A UTF-8 byte-order mark (some Windows editors write one) is not part of the TOML.
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        let error = |at: Option<usize>, message: String| SceneError {
            file: file.to_owned(),
            line: at.map(|a| line_of(text, a)),
            message,
        };
        let doc = check::Located::parse(text).map_err(|(at, m)| error(at, m))?;
        doc.check().map_err(|(at, m)| error(at, m))?;
        let de = toml::de::Deserializer::parse(text).map_err(|e| {
            let (at, message) = check::syntax_error(text, &e);
            error(at, message)
        })?;
        let scene: Scene = serde_path_to_error::deserialize(de).map_err(|e| {
            let path = e.path().to_string();
            let inner = e.into_inner();
            error(inner.span().map(|s| s.start), explain(&path, inner.message()))
        })?;
        scene.validate().map_err(|(path, message)| match doc.offset_of(path) {
            Some(at) => error(Some(at), message),
            // The key holds its default: the message says so, at the line of the key that set
            // the bound it breaks.
            None => {
                let bound = BOUND_BY.iter().find(|(k, _)| *k == path).map(|(_, b)| *b);
                let hint = match bound {
                    Some(b) => format!(
                        " ({path} is not in the file: that is its default, out of range for the {b} given; set {path})"
                    ),
                    None => format!(" ({path} is not in the file: that is its default)"),
                };
                error(bound.and_then(|b| doc.offset_of(b)), format!("{message}{hint}"))
            }
        })?;
        Ok(scene)
    }

    /// The 1-based line of the key `path` (dotted, `output.aovs`) in the scene text `text`, when
    /// the text sets it: for messages about a scene once it is loaded.
    pub fn line_of_key(text: &str, path: &str) -> Option<usize> {
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        check::Located::parse(text).ok()?.offset_of(path).map(|at| line_of(text, at))
    }

    /// The camera's view when neither `look_at` nor the angles are given: yaw 100°, pitch −9°.
    pub const DEFAULT_YAW_DEG: f64 = 100.0;
    /// See [`Scene::DEFAULT_YAW_DEG`].
    pub const DEFAULT_PITCH_DEG: f64 = -9.0;

    /// Checks the output against the scene once the command line has set its path: AOVs need an
    /// EXR file.
    ///
    /// # Errors
    /// A message naming `output.aovs` and the path.
    pub fn check_output(&self) -> Result<(), String> {
        let format = crate::output::OutputFormat::from_path(&self.output.path)?;
        if self.output.aovs && format != crate::output::OutputFormat::Exr {
            return Err(format!(
                "output.aovs = true needs an .exr output, but the output is {} (PNG has no extra channels)",
                self.output.path.display()
            ));
        }
        Ok(())
    }

    /// Checks the constraints between keys (each key's own type and range are the key table's,
    /// checked before); the error names the key (dotted path) whose line is shown.
    pub(super) fn validate(&self) -> Result<(), (&'static str, String)> {
        let c = &self.camera;
        if c.look_at.is_some() && (c.yaw_deg.is_some() || c.pitch_deg.is_some()) {
            return Err((
                "camera.look_at",
                "camera.look_at cannot be combined with yaw_deg/pitch_deg: give one or the other".into(),
            ));
        }
        if let Some(t) = c.look_at {
            let d = [t[0] - c.position[0], t[1] - c.position[1], t[2] - c.position[2]];
            let len2: f64 = d.iter().map(|x| x * x).sum();
            if !(len2 > 1e-12) || !len2.is_finite() {
                return Err(("camera.look_at", "camera.look_at must differ from camera.position".into()));
            }
        }
        let s = &self.sea;
        if s.spectrum == SpectrumKind::Tma && s.depth_m.is_none() {
            return Err(("sea.spectrum", "sea.spectrum = \"tma\" needs sea.depth_m (the water depth, m)".into()));
        }
        if let Some(w) = &s.swell {
            // A deep-water swell steeper than H_s/L = 1/7 (Michell's limit of a single wave, with
            // L = g T²/2π) cannot exist.
            let (h, t) = (w.significant_height_m, w.peak_period_s);
            let limit = brine_waves::G * t * t / std::f64::consts::TAU / 7.0;
            if h > limit {
                return Err((
                    "sea.swell.significant_height_m",
                    format!(
                        "sea.swell.significant_height_m = {h} is out of range: expected at most {limit:.2} m for a {t} s swell (H/L ≤ 1/7)"
                    ),
                ));
            }
        }
        let k = &self.sky;
        if self.place.is_some() && (k.sun_elevation_deg.is_some() || k.sun_azimuth_deg.is_some()) {
            let key = if k.sun_elevation_deg.is_some() { "sun_elevation_deg" } else { "sun_azimuth_deg" };
            let path = if k.sun_elevation_deg.is_some() { "sky.sun_elevation_deg" } else { "sky.sun_azimuth_deg" };
            return Err((
                path,
                format!("sky.{key} cannot be combined with [place], which sets the sun: give one or the other"),
            ));
        }
        let w = &self.water;
        if w.water_type.is_some() && w.chlorophyll_mg_m3.is_some() {
            return Err((
                "water.chlorophyll_mg_m3",
                "water.type and water.chlorophyll_mg_m3 exclude each other: give one".into(),
            ));
        }
        if let (Some(tw), Some(ta)) = (w.temperature_c, w.air_temperature_c) {
            // Monahan & Ó Muircheartaigh 1986's stability fit covers ΔT = T_w − T_a in [−30, 30] °C.
            // The difference of two decimal inputs carries their rounding (12.7 − 42.7 is
            // −30.000000000000004): it is compared with that much room.
            let dt = tw - ta;
            if dt.abs() > MAX_STABILITY_DIFFERENCE_C + DECIMAL_ROUNDING_C {
                return Err((
                    "water.air_temperature_c",
                    format!(
                        "water.air_temperature_c = {ta} is out of range: expected a water–air difference within ±30 °C (Monahan 1986's fit), got {:.3} °C",
                        dt
                    ),
                ));
            }
        }
        if let Some(f) = &w.floor {
            if f.amplitude_m > 0.5 * f.depth_m {
                return Err((
                    "water.floor.amplitude_m",
                    format!(
                        "water.floor.amplitude_m = {} is out of range: expected [0, depth_m/2] = [0, {}] m",
                        f.amplitude_m,
                        0.5 * f.depth_m
                    ),
                ));
            }
            let [lo, hi] = f.wavelength_range_m;
            if lo > hi {
                return Err((
                    "water.floor.wavelength_range_m",
                    format!(
                        "water.floor.wavelength_range_m = [{lo}, {hi}]: the shortest wavelength must come first (min ≤ max)"
                    ),
                ));
            }
        }
        Ok(())
    }
}

/// Keys whose range another key sets: a default out of the range that key gives is reported
/// at that key's line.
const BOUND_BY: [(&str, &str); 1] = [("water.floor.amplitude_m", "water.floor.depth_m")];

/// Widest water–air temperature difference of Monahan & Ó Muircheartaigh 1986's stability fit (°C).
pub(super) const MAX_STABILITY_DIFFERENCE_C: f64 = 30.0;

/// Room for the rounding of a difference of two temperatures written with a few decimals (°C):
/// far below any physical meaning, far above f64 rounding of values within ±50 °C (10⁻¹⁴).
pub(super) const DECIMAL_ROUNDING_C: f64 = 1e-9;

/// 1-based line of byte offset `at` in `text`.
pub(super) fn line_of(text: &str, at: usize) -> usize {
    text.as_bytes()[..at.min(text.len())].iter().filter(|&&b| b == b'\n').count() + 1
}

/// Rewrites serde's messages into what the user should have written, naming the key.
pub(super) fn explain(path: &str, message: &str) -> String {
    let message = message.trim();
    let found = message
        .strip_prefix("invalid type: ")
        .or_else(|| message.strip_prefix("invalid value: "))
        .and_then(|m| m.split_once(", expected "));
    if let Some((found, expected)) = found {
        let what = match expected {
            "f64" | "f32" => "a number".to_owned(),
            "u8" | "u16" | "u32" | "u64" | "usize" => "a non-negative whole number".to_owned(),
            "i32" | "i64" => "a whole number".to_owned(),
            "a boolean" => "true or false".to_owned(),
            e if e.starts_with("an array of length") || e.starts_with("a sequence") || e.starts_with("a tuple") => {
                format!("an array ({e})")
            }
            e => e.to_owned(),
        };
        return format!("expected {what} for {path}, found {found}");
    }
    if let Some(rest) = message.strip_prefix("unknown field ") {
        let (name, expected) = rest.split_once(", expected ").unwrap_or((rest, ""));
        let name = name.trim_matches('`');
        let key = if path.is_empty() || path == "." {
            name.to_owned()
        } else if path == name || path.ends_with(&format!(".{name}")) {
            path.to_owned()
        } else {
            format!("{path}.{name}")
        };
        return format!("unknown key {key} (expected {})", expected.replace('`', ""));
    }
    if let Some(rest) = message.strip_prefix("unknown variant ") {
        return format!("unknown value {} for {path}", rest.replace('`', ""));
    }
    format!("{path}: {message}")
}
