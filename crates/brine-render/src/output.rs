//! Image files, written atomically: to a temporary file in the destination folder, renamed over
//! the destination only once complete, so an interrupted render never leaves a half image.

use std::io::{BufWriter, Write};
use std::path::Path;

use glam::DVec3;

use crate::tonemap::{exposure_scale, to_srgb8};

/// Output file formats, chosen by the extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OutputFormat {
    /// 8-bit sRGB PNG, exposed and tone-mapped.
    Png,
    /// OpenEXR, linear sRGB radiance (kcd m⁻²) as 32-bit floats.
    Exr,
}

impl OutputFormat {
    /// The format of `path`'s extension.
    ///
    /// # Errors
    /// A message naming the extension if it is neither `.png` nor `.exr`.
    pub fn from_path(path: &Path) -> Result<Self, String> {
        match path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() {
            Some("png") => Ok(Self::Png),
            Some("exr") => Ok(Self::Exr),
            Some(other) => {
                Err(format!("output.path {}: unsupported extension .{other} (expected .png or .exr)", path.display()))
            }
            None => Err(format!("output.path {}: no extension (expected .png or .exr)", path.display())),
        }
    }
}

/// Why an image could not be written.
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    /// Unsupported path.
    #[error("{0}")]
    Format(String),
    /// File system error.
    #[error("cannot write {path}: {source}")]
    Io {
        /// Destination.
        path: String,
        /// Cause.
        source: std::io::Error,
    },
    /// Encoder error.
    #[error("cannot encode {path}: {message}")]
    Encode {
        /// Destination.
        path: String,
        /// Cause.
        message: String,
    },
}

/// Writes `pixels` (row-major, top row first, linear sRGB radiance in kcd m⁻²) to `path` in the
/// format of its extension, atomically.
///
/// # Errors
/// [`OutputError`] if the extension is unsupported, the folder is not writable, or encoding fails;
/// the destination is then untouched.
pub fn write_image(
    path: &Path,
    width: u32,
    height: u32,
    pixels: &[DVec3],
    exposure_ev: f64,
) -> Result<(), OutputError> {
    write_with_aovs(path, width, height, pixels, None, exposure_ev)
}

/// Writes a rendered frame; with `aovs` and an `.exr` path, the output variables become extra
/// channels of the same part, named as layers the way compositing tools read them: `depth.Z`,
/// `normal.X/Y/Z`, `foam.Y`, `whitecap.Y`, `glint.Y`, `evaluations.Y` (beside `R`, `G`, `B`). PNG files hold
/// the tone-mapped image only.
///
/// # Errors
/// See [`write_image`].
pub fn write_frame(path: &Path, frame: &crate::Frame, exposure_ev: f64, aovs: bool) -> Result<(), OutputError> {
    let aov = aovs.then_some(frame.aovs.as_slice());
    write_with_aovs(path, frame.width, frame.height, &frame.pixels, aov, exposure_ev)
}

fn write_with_aovs(
    path: &Path,
    width: u32,
    height: u32,
    pixels: &[DVec3],
    aovs: Option<&[crate::Aov]>,
    exposure_ev: f64,
) -> Result<(), OutputError> {
    let format = OutputFormat::from_path(path).map_err(OutputError::Format)?;
    let mut failed = None;
    let written = write_atomic(path, |w| {
        encode_image(w, format, width, height, pixels, aovs, exposure_ev).map_err(|message| {
            failed = Some(message.clone());
            std::io::Error::other(message)
        })
    });
    match (written, failed) {
        (Err(_), Some(message)) => Err(OutputError::Encode { path: path.display().to_string(), message }),
        (result, _) => result,
    }
}

/// Encodes 8-bit sRGB pixels (`RGB` rows, top to bottom) as a PNG tagged sRGB: the `sRGB` chunk
/// (perceptual intent) and, for readers that know only those, the `gAMA` and `cHRM` values the PNG
/// specification gives for sRGB (§11.3.2.5), so that colour-managed viewers show the colours the
/// renderer encoded.
pub(crate) fn encode_srgb_png(w: impl Write, width: u32, height: u32, rgb8: &[u8]) -> Result<(), png::EncodingError> {
    let mut encoder = png::Encoder::new(w, width, height);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
    // 1/2.2 scaled by 10⁵, and the D65 white and Rec. 709 primaries.
    encoder.set_source_gamma(png::ScaledFloat::from_scaled(45_455));
    let xy = |x: u32, y: u32| (png::ScaledFloat::from_scaled(x), png::ScaledFloat::from_scaled(y));
    encoder.set_source_chromaticities(png::SourceChromaticities {
        white: xy(31_270, 32_900),
        red: xy(64_000, 33_000),
        green: xy(30_000, 60_000),
        blue: xy(15_000, 6_000),
    });
    let mut writer = encoder.write_header()?;
    writer.write_image_data(rgb8)?;
    writer.finish()
}

/// Encodes an image into `w`.
fn encode_image(
    w: &mut BufWriter<&mut std::fs::File>,
    format: OutputFormat,
    width: u32,
    height: u32,
    pixels: &[DVec3],
    aovs: Option<&[crate::Aov]>,
    exposure_ev: f64,
) -> Result<(), String> {
    match format {
        OutputFormat::Png => {
            let scale = exposure_scale(exposure_ev);
            let mut bytes = Vec::with_capacity(pixels.len() * 3);
            for p in pixels {
                bytes.extend_from_slice(&to_srgb8(*p, scale));
            }
            encode_srgb_png(w, width, height, &bytes).map_err(|e| e.to_string())
        }
        OutputFormat::Exr => {
            let f32s = |f: &dyn Fn(usize) -> f32| (0..pixels.len()).map(f).collect::<Vec<f32>>();
            let mut channels = vec![
                ("R".to_owned(), f32s(&|i| pixels[i].x as f32)),
                ("G".to_owned(), f32s(&|i| pixels[i].y as f32)),
                ("B".to_owned(), f32s(&|i| pixels[i].z as f32)),
            ];
            if let Some(a) = aovs {
                let aov = |name: &str, f: &dyn Fn(usize) -> f32| (name.to_owned(), f32s(f));
                channels.push(aov("depth.Z", &|i| a[i].depth));
                channels.push(aov("normal.X", &|i| a[i].normal[0]));
                channels.push(aov("normal.Y", &|i| a[i].normal[1]));
                channels.push(aov("normal.Z", &|i| a[i].normal[2]));
                channels.push(aov("foam.Y", &|i| a[i].foam));
                channels.push(aov("whitecap.Y", &|i| a[i].whitecap));
                channels.push(aov("glint.Y", &|i| a[i].glint));
                channels.push(aov("evaluations.Y", &|i| a[i].evaluations));
            }
            encode_exr(w, width as usize, height as usize, channels)
        }
    }
}

/// Encodes named f32 channels (row-major, top row first) as one OpenEXR layer into `w`.
///
/// # Errors
/// The encoder's message.
pub fn encode_exr(
    w: &mut BufWriter<&mut std::fs::File>,
    width: usize,
    height: usize,
    channels: Vec<(String, Vec<f32>)>,
) -> Result<(), String> {
    use exr::prelude::*;
    let channels: Vec<AnyChannel<FlatSamples>> =
        channels.into_iter().map(|(name, v)| AnyChannel::new(name.as_str(), FlatSamples::F32(v))).collect();
    let layer = Layer::new(
        (width, height),
        LayerAttributes::named("brine"),
        Encoding::SMALL_LOSSLESS,
        AnyChannels::sort(SmallVec::from_vec(channels)),
    );
    Image::from_layer(layer).write().to_buffered(w).map_err(|e| e.to_string())
}

/// Writes `path` atomically: `write` fills a temporary file in the destination folder, renamed
/// over `path` only once complete and synced; a signal meanwhile removes the temporary
/// ([`remove_temporaries_on_signal`]).
///
/// # Errors
/// [`OutputError::Io`] naming the path; the destination is then untouched.
pub fn write_atomic(
    path: &Path,
    write: impl FnOnce(&mut BufWriter<&mut std::fs::File>) -> std::io::Result<()>,
) -> Result<(), OutputError> {
    let shown = path.display().to_string();
    let io = |source| OutputError::Io { path: shown.clone(), source };
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("image");
    let prefix = format!(".{name}.");
    let mut builder = tempfile::Builder::new();
    builder.prefix(&prefix).suffix(".tmp");
    // tempfile creates files readable by the owner only; an output is an ordinary file (0666
    // before the umask).
    #[cfg(unix)]
    builder.permissions(std::os::unix::fs::PermissionsExt::from_mode(0o666));
    // Registered before the temporary exists, so that a signal at any moment finds it.
    let _guard = InProgress::register(path);
    let mut tmp = builder.tempfile_in(dir).map_err(io)?;
    {
        let mut w = BufWriter::new(tmp.as_file_mut());
        write(&mut w).map_err(io)?;
        w.flush().map_err(io)?;
    }
    tmp.as_file().sync_all().map_err(io)?;
    tmp.persist(path).map_err(|e| io(e.error))?;
    Ok(())
}

/// Outputs being written: on a signal, their temporaries are removed
/// ([`remove_temporaries_on_signal`]).
static IN_PROGRESS: std::sync::Mutex<Vec<std::path::PathBuf>> = std::sync::Mutex::new(Vec::new());

/// An output registered as being written, from before its temporary file is made until after it
/// is renamed into place.
struct InProgress(std::path::PathBuf);

impl InProgress {
    fn register(path: &Path) -> Self {
        IN_PROGRESS.lock().unwrap_or_else(std::sync::PoisonError::into_inner).push(path.to_path_buf());
        Self(path.to_path_buf())
    }
}

impl Drop for InProgress {
    fn drop(&mut self) {
        let mut list = IN_PROGRESS.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
        list.retain(|p| p != &self.0);
    }
}

/// Installs a SIGINT/SIGTERM (Ctrl-C) handler that removes the temporary files being written and
/// ends the process with exit code 130, so that an interrupted render leaves no temporary file
/// (an existing output is never touched: it is replaced only by a complete file's rename).
/// SIGKILL cannot be caught; `--resume` removes what it leaves ([`remove_stale_temporaries`]).
///
/// The handler is installed once per process; later calls return the first one's result.
///
/// # Errors
/// A message if a handler cannot be installed (another one is already installed, for instance).
pub fn remove_temporaries_on_signal() -> Result<(), String> {
    static INSTALLED: std::sync::OnceLock<Result<(), String>> = std::sync::OnceLock::new();
    INSTALLED
        .get_or_init(|| {
            ctrlc::set_handler(|| {
                let list = IN_PROGRESS.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
                for p in list.iter() {
                    remove_stale_temporaries(p);
                }
                eprintln!("\ninterrupted: no partial output was left");
                std::process::exit(130);
            })
            .map_err(|e| format!("cannot install the signal handler: {e}"))
        })
        .clone()
}

/// Checks, before a long render, that `path` can be written: not a folder, in an existing folder
/// where a file can be created (a trial temporary file, removed at once).
///
/// # Errors
/// A message naming the path and the cause.
pub fn check_writable(path: &Path) -> Result<(), String> {
    let shown = path.display();
    if path.is_dir() {
        return Err(format!("cannot write {shown}: it is a folder (give a file name)"));
    }
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    if !dir.is_dir() {
        return Err(format!("cannot write {shown}: folder {} does not exist", dir.display()));
    }
    let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("image");
    tempfile::Builder::new()
        .prefix(&format!(".{name}."))
        .suffix(".tmp")
        .tempfile_in(dir)
        .map(drop)
        .map_err(|e| format!("cannot write {shown}: cannot create a file in {}: {e}", dir.display()))
}

/// Whether `path` holds a complete image of its format (PNG or EXR), decoded to the last pixel:
/// what `--resume` asks of a frame before it skips it.
pub fn decodes_completely(path: &Path) -> bool {
    match OutputFormat::from_path(path) {
        Ok(OutputFormat::Png) => image::ImageReader::open(path)
            .ok()
            .and_then(|r| r.with_guessed_format().ok())
            .is_some_and(|r| r.decode().is_ok()),
        Ok(OutputFormat::Exr) => exr::prelude::read_all_data_from_file(path).is_ok(),
        Err(_) => false,
    }
}

/// The size `(width, height)` of the complete image of its format (PNG or EXR) at `path`,
/// decoded to the last pixel; `None` when it is missing, cut short or not an image.
pub fn decoded_size(path: &Path) -> Option<(usize, usize)> {
    match OutputFormat::from_path(path).ok()? {
        OutputFormat::Png => {
            let img = image::ImageReader::open(path).ok()?.with_guessed_format().ok()?.decode().ok()?;
            Some((img.width() as usize, img.height() as usize))
        }
        OutputFormat::Exr => {
            let img = exr::prelude::read_all_data_from_file(path).ok()?;
            let size = img.layer_data.first()?.size;
            Some((size.0, size.1))
        }
    }
}

/// Removes the temporary files that an interrupted write of `path` left beside it
/// (`.NAME.XXXXXX.tmp`, the names [`write_image`] uses), e.g. after a SIGKILL.
///
/// # Returns
/// How many were removed.
pub fn remove_stale_temporaries(path: &Path) -> usize {
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    let Some(name) = path.file_name().and_then(|n| n.to_str()) else { return 0 };
    let prefix = format!(".{name}.");
    let Ok(entries) = std::fs::read_dir(dir) else { return 0 };
    let mut removed = 0;
    for e in entries.flatten() {
        let file = e.file_name();
        let Some(f) = file.to_str() else { continue };
        // tempfile's random part: six alphanumeric characters between the prefix and ".tmp".
        let is_ours = f
            .strip_prefix(&prefix)
            .and_then(|r| r.strip_suffix(".tmp"))
            .is_some_and(|mid| mid.len() == 6 && mid.bytes().all(|b| b.is_ascii_alphanumeric()));
        if is_ours && std::fs::remove_file(e.path()).is_ok() {
            removed += 1;
        }
    }
    removed
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unsupported_extensions_are_named() {
        let e = OutputFormat::from_path(Path::new("a.jpg")).unwrap_err();
        assert!(e.contains(".jpg"), "{e}");
        assert_eq!(OutputFormat::from_path(Path::new("A.PNG")), Ok(OutputFormat::Png));
    }

    /// A PNG is tagged sRGB (with the specification's gAMA and cHRM for older readers) and holds
    /// the pixels `to_srgb8` encoded.
    #[test]
    fn png_images_are_tagged_srgb() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("x.png");
        let pixels = [DVec3::new(0.02, 0.2, 0.9), DVec3::ZERO, DVec3::ONE, DVec3::splat(0.5)];
        write_image(&path, 2, 2, &pixels, 0.0).unwrap();
        let reader =
            png::Decoder::new(std::io::BufReader::new(std::fs::File::open(&path).unwrap())).read_info().unwrap();
        assert_eq!(reader.info().srgb, Some(png::SrgbRenderingIntent::Perceptual));
        // The chunks as written (a decoder reads gAMA and cHRM only where sRGB is missing).
        let bytes = std::fs::read(&path).unwrap();
        let mut chunks = Vec::new();
        let mut at = 8;
        while at + 8 <= bytes.len() {
            let n = u32::from_be_bytes(bytes[at..at + 4].try_into().unwrap()) as usize;
            chunks.push((
                String::from_utf8_lossy(&bytes[at + 4..at + 8]).into_owned(),
                bytes[at + 8..at + 8 + n].to_vec(),
            ));
            at += 12 + n;
        }
        let chunk = |name: &str| chunks.iter().find(|(n, _)| n == name).map(|(_, d)| d.clone());
        assert_eq!(chunk("gAMA"), Some(45_455u32.to_be_bytes().to_vec()));
        let chrm = chunk("cHRM").expect("cHRM");
        assert_eq!(chrm[..8], [31_270u32.to_be_bytes(), 32_900u32.to_be_bytes()].concat());
        let decoded = image::open(&path).unwrap().to_rgb8();
        let scale = exposure_scale(0.0);
        for (p, q) in pixels.iter().zip(decoded.pixels()) {
            assert_eq!(to_srgb8(*p, scale), q.0);
        }
    }

    #[test]
    fn a_failed_write_leaves_nothing() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("missing-folder").join("x.png");
        assert!(write_image(&path, 1, 1, &[DVec3::ONE], 14.0).is_err());
        assert!(!path.exists());
        let ok = dir.path().join("x.exr");
        write_image(&ok, 1, 1, &[DVec3::ONE], 14.0).unwrap();
        assert!(ok.exists());
        let meta = std::fs::metadata(&ok).unwrap();
        #[cfg(unix)]
        assert_ne!(std::os::unix::fs::PermissionsExt::mode(&meta.permissions()) & 0o044, 0, "others can read");
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1, "no temporary file left");
    }
}
