//! The table of every scene key: its type, unit, range, default and meaning.
//!
//! One table drives both the validator (each key's type and range are checked against it, on the
//! parsed TOML, before the values reach the scene structs) and the key tables of `docs/scene.md`
//! (generated from it by [`markdown_table`]; a test fails when the page is stale). Checks that
//! involve two keys (`look_at` against `yaw_deg`, a swell's height against its period, …) are
//! written out in the scene's `validate`, and named in the `range` column through
//! [`KeySpec::note`].

/// What a key holds and the values it accepts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Kind {
    /// A number in an interval (integers are accepted for numbers). `None` bounds are open to
    /// infinity; a number is always finite.
    Float {
        /// Lower bound and whether it is included.
        lo: Option<(f64, bool)>,
        /// Upper bound and whether it is included.
        hi: Option<(f64, bool)>,
    },
    /// A whole number in `[lo, hi]`.
    Int {
        /// Smallest value.
        lo: i128,
        /// Largest value.
        hi: i128,
    },
    /// A power of two in `[lo, hi]`.
    PowerOfTwo {
        /// Smallest value.
        lo: i128,
        /// Largest value.
        hi: i128,
    },
    /// `true` or `false`.
    Bool,
    /// One of a list of strings.
    Enum {
        /// The accepted values.
        values: &'static [&'static str],
        /// Whether case is ignored (water types: `ib` is `IB`).
        ignore_case: bool,
    },
    /// A UTC instant (RFC 3339) in the years 1800–2200.
    Instant,
    /// A file path ending in `.png` or `.exr`.
    ImagePath,
    /// An array of exactly `len` numbers, each in `[lo, hi]`.
    FloatArray {
        /// Number of elements.
        len: usize,
        /// Smallest element.
        lo: f64,
        /// Largest element.
        hi: f64,
    },
}

/// One scene key.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KeySpec {
    /// Section, dotted (`sea.swell`).
    pub section: &'static str,
    /// Key inside the section.
    pub key: &'static str,
    /// Type and range.
    pub kind: Kind,
    /// Unit as printed in the docs (`m/s`, `°`, `1` for a plain number, `—` for none).
    pub unit: &'static str,
    /// Default as printed in the docs (`—` when absent means "not set").
    pub default: &'static str,
    /// A constraint involving other keys, appended to the range in the docs.
    pub note: Option<&'static str>,
    /// What it means.
    pub meaning: &'static str,
}

impl KeySpec {
    /// The full dotted path, `sea.swell.waves`.
    pub fn path(&self) -> String {
        format!("{}.{}", self.section, self.key)
    }

    /// The accepted values in words, as in messages and the docs (`[0, 60] m/s`).
    pub fn expected(&self) -> String {
        let unit = match self.unit {
            "1" | "—" | "" => String::new(),
            u => format!(" {u}"),
        };
        match self.kind {
            Kind::Float { lo: None, hi: None } => "a finite number".to_owned() + &unit,
            Kind::Float { lo, hi } => format!("{}{unit}", interval(lo, hi)),
            Kind::Int { lo, hi } if hi >= i128::from(i64::MAX) => format!("a whole number ≥ {lo}"),
            Kind::Int { lo, hi } => format!("a whole number in [{lo}, {hi}]{unit}"),
            Kind::PowerOfTwo { lo, hi } => format!("a power of two in [{lo}, {hi}]"),
            Kind::Bool => "true or false".to_owned(),
            Kind::Enum { values, .. } => {
                let quoted: Vec<String> = values.iter().map(|v| format!("\"{v}\"")).collect();
                format!("one of {}", quoted.join(", "))
            }
            Kind::Instant => {
                "a UTC instant (RFC 3339, e.g. \"2024-06-21T09:30:00Z\") in the years 1800–2200".to_owned()
            }
            Kind::ImagePath => "a file name ending in .png or .exr".to_owned(),
            Kind::FloatArray { len, lo, hi } if lo.to_bits() == (-hi).to_bits() => {
                format!("an array of {len} numbers, each within ±{}{unit}", num(hi))
            }
            Kind::FloatArray { len, lo, hi } => {
                format!("an array of {len} numbers, each in [{}, {}]{unit}", num(lo), num(hi))
            }
        }
    }

    /// The range column of the docs.
    fn range_doc(&self) -> String {
        let base = match self.kind {
            Kind::Float { lo: None, hi: None } => "finite".to_owned(),
            Kind::Float { lo, hi } => interval(lo, hi),
            Kind::Int { hi, .. } if hi >= i128::from(i64::MAX) => "whole, ≥ 0".to_owned(),
            Kind::Int { lo, hi } => format!("[{lo}, {hi}]"),
            Kind::PowerOfTwo { lo, hi } => format!("power of two in [{lo}, {hi}]"),
            Kind::Bool => "bool".to_owned(),
            Kind::Enum { values, .. } => values.iter().map(|v| format!("`{v}`")).collect::<Vec<_>>().join(", "),
            Kind::Instant => "RFC 3339, years 1800–2200".to_owned(),
            Kind::ImagePath => "`.png` or `.exr`".to_owned(),
            Kind::FloatArray { len, lo, hi } if lo.to_bits() == (-hi).to_bits() => {
                format!("{len} numbers, each within ±{}", num(hi))
            }
            Kind::FloatArray { len, lo, hi } => format!("{len} numbers, each in [{}, {}]", num(lo), num(hi)),
        };
        match self.note {
            Some(n) => format!("{base}; {n}"),
            None => base,
        }
    }
}

/// An interval as printed, `[0, 60]`, `(0, 20000]`, with `None` ends at infinity.
fn interval(lo: Option<(f64, bool)>, hi: Option<(f64, bool)>) -> String {
    let l = lo.map_or_else(|| "(−∞".to_owned(), |(v, inc)| format!("{}{}", if inc { '[' } else { '(' }, num(v)));
    let h = hi.map_or_else(|| "∞)".to_owned(), |(v, inc)| format!("{}{}", num(v), if inc { ']' } else { ')' }));
    format!("{l}, {h}")
}

/// A bound as printed: whole numbers without a decimal point, powers of ten as `10⁶`.
#[allow(clippy::float_cmp)] // exact: the bounds are these literals, not results of arithmetic
fn num(v: f64) -> String {
    for (p, s) in [(1e4, "10⁴"), (1e5, "10⁵"), (1e6, "10⁶")] {
        if v == p {
            return s.to_owned();
        }
        if v == -p {
            return format!("−{s}");
        }
    }
    if v < 0.0 { format!("−{}", -v) } else { format!("{v}") }
}

/// The sections that are tables of keys, outermost first.
pub const SECTIONS: &[&str] = &[
    "place",
    "camera",
    "sea",
    "sea.fft",
    "sea.swell",
    "water",
    "water.floor",
    "sky",
    "sky.clouds",
    "phenomena",
    "output",
    "animation",
];

const fn closed(lo: f64, hi: f64) -> Kind {
    Kind::Float { lo: Some((lo, true)), hi: Some((hi, true)) }
}

const fn left_open(lo: f64, hi: f64) -> Kind {
    Kind::Float { lo: Some((lo, false)), hi: Some((hi, true)) }
}

const fn open(lo: f64, hi: f64) -> Kind {
    Kind::Float { lo: Some((lo, false)), hi: Some((hi, false)) }
}

const FINITE: Kind = Kind::Float { lo: None, hi: None };
const SEED: Kind = Kind::Int { lo: 0, hi: u64::MAX as i128 };
const BOOL: Kind = Kind::Bool;

const fn k(
    section: &'static str,
    key: &'static str,
    kind: Kind,
    unit: &'static str,
    default: &'static str,
    meaning: &'static str,
) -> KeySpec {
    KeySpec { section, key, kind, unit, default, note: None, meaning }
}

const fn with_note(spec: KeySpec, note: &'static str) -> KeySpec {
    KeySpec { note: Some(note), ..spec }
}

/// Every key of a scene file.
pub const KEYS: &[KeySpec] = &[
    // [place]
    k("place", "latitude_deg", closed(-90.0, 90.0), "°", "required", "geodetic latitude, north positive"),
    k("place", "longitude_deg", closed(-180.0, 180.0), "°", "required", "longitude, east positive"),
    k("place", "time_utc", Kind::Instant, "—", "required", "UTC instant of frame 0, e.g. `\"2024-06-21T09:30:00Z\"`"),
    k(
        "place",
        "sun_model",
        Kind::Enum { values: &["spa", "schlyter"], ignore_case: false },
        "—",
        "`\"spa\"`",
        "NREL SPA (published ±0.0003°; measured ≤ 0.0015° against ERFA) or Schlyter's model (~0.01°, the paper's)",
    ),
    k("place", "refraction", BOOL, "—", "`true`", "atmospheric refraction of sun and moon near the horizon"),
    // [camera]
    k(
        "camera",
        "position",
        Kind::FloatArray { len: 3, lo: -1e6, hi: 1e6 },
        "m",
        "`[0, 10, 0]`",
        "eye position; y up, sea level y = 0; below the surface renders the underwater view",
    ),
    with_note(
        k("camera", "look_at", Kind::FloatArray { len: 3, lo: -1e6, hi: 1e6 }, "m", "—", "point looked at"),
        "≠ `position`; excludes `yaw_deg` and `pitch_deg`",
    ),
    k("camera", "yaw_deg", FINITE, "°", "100", "compass bearing of the view (0 north, 90 east)"),
    k("camera", "pitch_deg", closed(-90.0, 90.0), "°", "−9", "elevation of the view (negative looks down)"),
    k("camera", "fov_deg", open(0.0, 180.0), "°", "50", "vertical field of view"),
    k("camera", "width", Kind::Int { lo: 1, hi: 16384 }, "px", "1280", "image width"),
    k("camera", "height", Kind::Int { lo: 1, hi: 16384 }, "px", "720", "image height"),
    k(
        "camera",
        "spp",
        Kind::Int { lo: 1, hi: 4096 },
        "1",
        "1",
        "samples per pixel (1: pixel centre; more: jittered from the seed, each filtering over `max(1/8, 1/√spp)` of the pixel's footprint)",
    ),
    // [sea]
    k(
        "sea",
        "spectrum",
        Kind::Enum { values: &["pierson-moskowitz", "jonswap", "phillips", "tma", "elfouhaily"], ignore_case: false },
        "—",
        "`\"pierson-moskowitz\"`",
        "ocean spectrum of the fit",
    ),
    k(
        "sea",
        "spreading",
        Kind::Enum {
            values: &["auto", "cos2s", "mitsuyasu", "donelan-banner", "cos-squared", "elfouhaily"],
            ignore_case: false,
        },
        "—",
        "`\"auto\"`",
        "directional spreading (`auto`: Elfouhaily's Δ(k) for `elfouhaily`, Hasselmann cos-2s otherwise)",
    ),
    k(
        "sea",
        "surface",
        Kind::Enum { values: &["trochoids", "gerstner", "sine", "fft"], ignore_case: false },
        "—",
        "`\"trochoids\"`",
        "surface traced (see renderer.md); `fft` is Tessendorf's inverse-FFT sea of the same spectrum (see `[sea.fft]`); `gerstner` renders about 6 times slower than `trochoids` at the same wave count (5.7 times in the default view, 6.8 at 14 m/s), more with the camera among the crests (its certified steps are first-order; docs/benchmarks.md)",
    ),
    k(
        "sea",
        "wind_speed_m_s",
        closed(0.0, 60.0),
        "m/s",
        "10",
        "U10, the wind 10 m above the sea; 0 is a flat calm, as is a wind too light to raise waves a millimetre long (under about 0.02 m/s)",
    ),
    k(
        "sea",
        "wind_direction_deg",
        FINITE,
        "°",
        "20",
        "direction the wind blows toward, from +x (east) toward +z (south)",
    ),
    k(
        "sea",
        "fetch_km",
        closed(0.1, 1e5),
        "km",
        "—",
        "fetch of `jonswap`, `tma`, `elfouhaily` (fully developed when absent; JONSWAP/TMA then use 100 km)",
    ),
    k("sea", "gamma", closed(1.0, 10.0), "1", "3.3", "JONSWAP/TMA peak enhancement"),
    with_note(k("sea", "depth_m", closed(0.5, 1e4), "m", "—", "water depth of `tma`"), "required by `tma`"),
    k(
        "sea",
        "waves",
        Kind::Int { lo: 0, hi: 10_000 },
        "1",
        "150 (`trochoids`), 50",
        "number of waves of the wind sea (trochoid, Gerstner and sine surfaces; not used by `fft`); by default 150 trochoids (their shorter waves on grids) and 50 Gerstner or sine waves (traced one by one)",
    ),
    k(
        "sea",
        "choppiness",
        closed(0.0, 100.0),
        "1",
        "2.5",
        "steepness multiplier `c` in `Q = c·kA`; all Q scaled down together if ΣQ > 0.9 (trochoid fit; `fft` has its own)",
    ),
    k(
        "sea",
        "grid",
        Kind::Enum { values: &["auto", "on", "off"], ignore_case: false },
        "—",
        "`\"auto\"`",
        "`trochoids` only: the waves shorter than 0.4 λ_max snapped band by band to periodic tiles (about seven, of sides 2.2 apart) and traced on grids, certified for the snapped waves, which are then the sea (`auto`: from 150 waves up, where it pays; the 400-wave reference frame takes about 2.2 times the 50-wave frame's time instead of 4.0; docs/models/brine-waves.md)",
    ),
    k("sea", "seed", SEED, "1", "1", "seed of wave directions and phases, foam noise and pixel jitter"),
    k("sea", "time_s", closed(0.0, 1e6), "s", "0", "wave time of frame 0"),
    k(
        "sea",
        "trace_distance_m",
        closed(10.0, 1e6),
        "m",
        "3000",
        "waves are traced as geometry up to here; beyond, the Earth's curved mean sea with all slopes in the BRDF, out to the horizon",
    ),
    // [sea.fft]
    k(
        "sea.fft",
        "resolution",
        Kind::PowerOfTwo { lo: 64, hi: 2048 },
        "1",
        "256",
        "grid points per side of every cascade",
    ),
    k(
        "sea.fft",
        "cascades",
        Kind::Int { lo: 1, hi: 8 },
        "1",
        "4",
        "number of cascades (4: from ~8 peak wavelengths down to millimetre capillaries at 256²)",
    ),
    k(
        "sea.fft",
        "choppiness",
        closed(0.0, 4.0),
        "1",
        "1",
        "horizontal displacement factor λ (0: the plain height field)",
    ),
    k(
        "sea.fft",
        "loop_period_s",
        left_open(0.0, 1e6),
        "s",
        "—",
        "when given, every frequency is rounded to a multiple of 2π/T: the animation loops exactly after T; a wave of period P then runs up to P/(2T) off its speed, and one longer than 2T turns once per loop (warned of when that moves much of the sea: about 100 s keeps a 10 m/s sea within 5 %)",
    ),
    k(
        "sea.fft",
        "blend",
        BOOL,
        "—",
        "`true`",
        "read every cascade through a tile and blend, so that the sea does not repeat with its tiles; false: the periodic tiles, about 2.3× faster, repeating in aerial views",
    ),
    // [sea.swell]
    with_note(
        k(
            "sea.swell",
            "significant_height_m",
            left_open(0.0, 20.0),
            "m",
            "1",
            "H_s = 4√m₀ of the swell (no steeper than Michell's limit H/L = 1/7 at the peak wavelength)",
        ),
        "at most `g T_p²/(2π)/7`",
    ),
    k("sea.swell", "peak_period_s", closed(4.0, 30.0), "s", "12", "peak period"),
    k("sea.swell", "direction_deg", FINITE, "°", "0", "direction the swell travels toward, from +x toward +z"),
    k("sea.swell", "waves", Kind::Int { lo: 1, hi: 1000 }, "1", "12", "number of swell waves"),
    k(
        "sea.swell",
        "spreading_s",
        closed(1.0, 200.0),
        "1",
        "40",
        "exponent of its cos-2s spreading (larger is narrower)",
    ),
    k("sea.swell", "gamma", closed(1.0, 10.0), "1", "3.3", "JONSWAP peak enhancement of the swell"),
    // [water]
    with_note(
        k(
            "water",
            "type",
            Kind::Enum {
                values: &["I", "IA", "IB", "II", "III", "1C", "3C", "5C", "7C", "9C", "clear", "turbid", "very-turbid"],
                ignore_case: true,
            },
            "—",
            "`\"IB\"`",
            "Jerlov water type (or Darles' classes, mapped to I, III, 5C); IB when neither this nor `chlorophyll_mg_m3` is given",
        ),
        "excludes `chlorophyll_mg_m3`",
    ),
    with_note(
        k("water", "chlorophyll_mg_m3", closed(0.0, 30.0), "mg/m³", "—", "Case-1 water of this chlorophyll (Morel)"),
        "excludes `type`",
    ),
    k(
        "water",
        "temperature_c",
        closed(-2.0, 40.0),
        "°C",
        "—",
        "sea temperature; with `air_temperature_c`, whitecaps follow Monahan 1986's stability law",
    ),
    with_note(
        k(
            "water",
            "air_temperature_c",
            closed(-40.0, 50.0),
            "°C",
            "—",
            "air temperature 10 m above the sea (the 1986 stability fit covers a water–air difference of ±30 °C)",
        ),
        "within ±30 °C of `temperature_c`",
    ),
    // [water.floor]
    k("water.floor", "depth_m", closed(0.5, 1000.0), "m", "6", "mean depth below sea level"),
    k(
        "water.floor",
        "albedo",
        Kind::FloatArray { len: 3, lo: 0.0, hi: 1.0 },
        "1",
        "`[0.45, 0.40, 0.30]`",
        "Lambertian reflectance (linear sRGB)",
    ),
    k("water.floor", "waves", Kind::Int { lo: 0, hi: 64 }, "1", "8", "trochoids shaping the floor (static)"),
    with_note(
        k("water.floor", "amplitude_m", closed(0.0, 500.0), "m", "0.4", "sum of their amplitudes"),
        "at most `depth_m/2`",
    ),
    with_note(
        k(
            "water.floor",
            "wavelength_range_m",
            Kind::FloatArray { len: 2, lo: 0.05, hi: 1e4 },
            "m",
            "`[0.8, 25]`",
            "shortest and longest wavelengths, log-spaced",
        ),
        "min ≤ max",
    ),
    k("water.floor", "seed", SEED, "1", "7", "directions and phases"),
    // [sky]
    k("sky", "turbidity", closed(1.7, 10.0), "1", "3", "atmospheric turbidity"),
    k(
        "sky",
        "model",
        Kind::Enum { values: &["preetham", "hosek-wilkie"], ignore_case: false },
        "—",
        "`\"preetham\"`",
        "clear daylight sky: Preetham et al. 1999 or Hosek & Wilkie 2012",
    ),
    with_note(k("sky", "sun_elevation_deg", closed(-90.0, 90.0), "°", "24", "sun elevation"), "only without `[place]`"),
    with_note(k("sky", "sun_azimuth_deg", FINITE, "°", "115", "compass bearing of the sun"), "only without `[place]`"),
    // [sky.clouds]
    k("sky.clouds", "cover", closed(0.0, 1.0), "1", "0.4", "fraction of the sky covered"),
    k("sky.clouds", "altitude_m", left_open(0.0, 20_000.0), "m", "2000", "cloud base"),
    k("sky.clouds", "scale_m", closed(10.0, 1e6), "m", "4000", "size of the largest features"),
    k(
        "sky.clouds",
        "wind_m_s",
        Kind::FloatArray { len: 2, lo: -100.0, hi: 100.0 },
        "m/s",
        "`[8, 0]`",
        "drift `[east, south]`",
    ),
    k("sky.clouds", "seed", SEED, "1", "1", "noise seed"),
    // [phenomena]
    k("phenomena", "glare", BOOL, "—", "`true`", "Spencer et al. 1995 point-spread function of the eye"),
    k(
        "phenomena",
        "aerial_perspective",
        BOOL,
        "—",
        "`true`",
        "Hoffman & Preetham extinction and in-scattering between the eye and the sea",
    ),
    k("phenomena", "clouds", BOOL, "—", "`true`", "the layers of `[sky.clouds]`"),
    k("phenomena", "subsurface", BOOL, "—", "`true`", "sun light through thin crests (Jensen dipole)"),
    k("phenomena", "foam", BOOL, "—", "`true`", "foam (left by breaking crests; alone: Darles/Koepke foam on crests)"),
    k("phenomena", "whitecaps", BOOL, "—", "`true`", "Dupuy–Bruneton whitecaps from the Jacobian"),
    k(
        "phenomena",
        "foam_memory",
        BOOL,
        "—",
        "`true`",
        "with foam and whitecaps: foam left by the breaking crests, drifting and decaying (`false`: the two drawn separately)",
    ),
    k(
        "phenomena",
        "spray",
        BOOL,
        "—",
        "`true`",
        "spray along the camera ray: Monahan bubble drops and Fairall spume (spume also toward the sky)",
    ),
    k(
        "phenomena",
        "whitecap_alpha",
        closed(-2.0, 2.0),
        "1",
        "—",
        "raw whitecap threshold α; when absent α is calibrated to Monahan's coverage",
    ),
    // [output]
    k("output", "path", Kind::ImagePath, "—", "`\"ocean.png\"`", "output file (the `-o` option overrides it)"),
    k(
        "output",
        "exposure_ev",
        closed(-10.0, 30.0),
        "EV₁₀₀",
        "automatic",
        "manual exposure: luminance `1.2·2^EV` cd/m² maps to white before the tone curve",
    ),
    k(
        "output",
        "exposure_compensation_ev",
        closed(-10.0, 10.0),
        "EV",
        "0",
        "brighter (+) or darker (−) than the automatic exposure",
    ),
    k(
        "output",
        "white_balance",
        Kind::Enum { values: &["none", "scene", "image"], ignore_case: false },
        "—",
        "`\"none\"`",
        "`\"scene\"`: the light of sun, moon and sky on a level surface shown as white; `\"image\"`: the image's mean colour shown as grey, as a camera's automatic white balance (both a Bradford adaptation to D65, the EXR too); `\"none\"`: the radiance as it is on a D65 display",
    ),
    with_note(
        k(
            "output",
            "aovs",
            BOOL,
            "—",
            "`false`",
            "depth, normal, foam, whitecap, sun glint (per unit irradiance, sr⁻¹), evaluations as extra EXR channels: of the pixel's centre at 1 sample per pixel, of its first sample (a random point in it, as Blender Cycles' depth pass) with more",
        ),
        "needs an `.exr` output (after `-o`)",
    ),
    // [animation]
    k(
        "animation",
        "fps",
        left_open(0.0, 1000.0),
        "1/s",
        "24",
        "frame `f` is at `sea.time_s + f/fps` and `place.time_utc + f/fps` (with `--time-lapse`, the place's time runs from START at frame 0 to END at the run's last frame instead, so the tail of a run, `--frames 100..240`, is the same frames as the whole run's)",
    ),
];

/// The spec of `section.key`, if there is one.
pub fn find(section: &str, key: &str) -> Option<&'static KeySpec> {
    KEYS.iter().find(|s| s.section == section && s.key == key)
}

/// The key table of one section as Markdown, as in `docs/scene.md`.
pub fn markdown_table(section: &str) -> String {
    let mut out = String::from("| key | unit | range | default | meaning |\n|---|---|---|---|---|\n");
    for s in KEYS.iter().filter(|s| s.section == section) {
        out += &format!("| `{}` | {} | {} | {} | {} |\n", s.key, s.unit, s.range_doc(), s.default, s.meaning);
    }
    out
}

/// `docs/scene.md` with every generated key table replaced by the current one: the tables sit
/// between `<!-- keys: SECTION -->` and `<!-- /keys -->` lines.
///
/// # Errors
/// A message naming a section whose block is missing or not closed.
pub fn regenerate_doc(doc: &str) -> Result<String, String> {
    let mut out = String::with_capacity(doc.len());
    let mut rest = doc;
    let mut seen = Vec::new();
    while let Some(at) = rest.find("<!-- keys: ") {
        let (before, from) = rest.split_at(at);
        out += before;
        let header_end = from.find("-->").ok_or("an unclosed <!-- keys: comment")? + 3;
        let section = from["<!-- keys: ".len()..header_end - 3].trim().to_owned();
        if !SECTIONS.contains(&section.as_str()) {
            return Err(format!("<!-- keys: {section} -->: no such section"));
        }
        let close = from.find("<!-- /keys -->").ok_or_else(|| format!("the block of {section} is not closed"))?;
        out += &from[..header_end];
        out += "\n";
        out += &markdown_table(&section);
        out += "<!-- /keys -->";
        rest = &from[close + "<!-- /keys -->".len()..];
        seen.push(section);
    }
    out += rest;
    for s in SECTIONS {
        if !seen.iter().any(|x| x == s) {
            return Err(format!("docs/scene.md has no <!-- keys: {s} --> block"));
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `docs/scene.md`, whose key tables are generated from [`KEYS`].
    const DOC: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../docs/scene.md");

    /// The key tables of docs/scene.md are the table's: regenerate them with
    /// `BRINE_UPDATE_DOCS=1 cargo test -p brine-render scene_doc`.
    #[test]
    fn scene_doc_tables_are_generated_from_the_key_table() {
        let doc = std::fs::read_to_string(DOC).expect("docs/scene.md is readable");
        let fresh = regenerate_doc(&doc).expect("every section has its block");
        if std::env::var_os("BRINE_UPDATE_DOCS").is_some() {
            std::fs::write(DOC, &fresh).expect("docs/scene.md is writable");
            return;
        }
        assert!(doc == fresh, "docs/scene.md is stale: run BRINE_UPDATE_DOCS=1 cargo test -p brine-render scene_doc");
    }

    /// Every field of the scene structs has its row, and every row a field: a scene with every
    /// optional part present, written back to TOML, holds exactly the table's keys.
    #[test]
    fn the_key_table_lists_every_field_of_the_scene() {
        let mut scene = crate::Scene::default_scene();
        scene.camera.look_at = Some([1.0, 0.0, 0.0]);
        scene.sea.fetch_km = Some(10.0);
        scene.sea.gamma = Some(3.3);
        scene.sea.depth_m = Some(20.0);
        scene.sea.waves = Some(150);
        scene.sea.fft.loop_period_s = Some(10.0);
        scene.sea.swell = Some(crate::scene::SwellConfig::default());
        scene.water.chlorophyll_mg_m3 = Some(0.1);
        scene.water.temperature_c = Some(10.0);
        scene.water.air_temperature_c = Some(10.0);
        scene.water.floor = Some(crate::scene::FloorConfig::default());
        scene.sky.sun_elevation_deg = Some(10.0);
        scene.sky.sun_azimuth_deg = Some(10.0);
        scene.sky.clouds = Some(crate::scene::CloudConfig::default());
        scene.phenomena.whitecap_alpha = Some(0.5);
        scene.output.exposure_ev = Some(10.0);
        let table: toml::Table = toml::from_str(&toml::to_string(&scene).unwrap()).unwrap();
        let mut written = Vec::new();
        fn walk(t: &toml::Table, prefix: &str, out: &mut Vec<String>) {
            for (k, v) in t {
                let path = if prefix.is_empty() { k.clone() } else { format!("{prefix}.{k}") };
                match v {
                    toml::Value::Table(inner) if SECTIONS.contains(&path.as_str()) => walk(inner, &path, out),
                    _ => out.push(path),
                }
            }
        }
        walk(&table, "", &mut written);
        written.sort();
        let mut listed: Vec<String> = KEYS.iter().map(KeySpec::path).collect();
        listed.sort();
        assert_eq!(written, listed);
        // And every section of the table is a section of the scene.
        for s in SECTIONS {
            assert!(KEYS.iter().any(|k| k.section == *s), "section {s} has no key");
        }
    }

    #[test]
    fn ranges_read_as_written() {
        assert_eq!(find("sea", "wind_speed_m_s").unwrap().expected(), "[0, 60] m/s");
        assert_eq!(find("sky.clouds", "altitude_m").unwrap().expected(), "(0, 20000] m");
        assert_eq!(find("sea", "trace_distance_m").unwrap().expected(), "[10, 10⁶] m");
        assert_eq!(find("sea.fft", "resolution").unwrap().expected(), "a power of two in [64, 2048]");
        assert!(find("sea", "nope").is_none());
    }
}
