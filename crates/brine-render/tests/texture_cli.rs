//! `brine texture` as a process: bad inputs (missing file, unsupported or corrupt format, an image smaller
//! than the patch, a uniform image) each give a clear message, exit code 2, no panic and no file
//! written; a good run writes the same bytes for the same seed.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The shipped example inputs.
fn example(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../brine-texture/examples").join(name)
}

/// Small synthesis sizes that keep a run quick in the dev profile.
const SMALL_RUN: &[&str] = &[
    "--small-size",
    "64",
    "--main-size",
    "64",
    "--patch",
    "24",
    "--boundary",
    "4",
    "--basis-frames",
    "3",
    "--links",
    "1",
    "--width",
    "48",
    "--height",
    "32",
];

/// Runs `brine texture ARGS` in `dir`.
fn texture(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_brine")).arg("texture").args(args).current_dir(dir).output().expect("brine runs")
}

/// Runs `brine texture --small SMALL --main MAIN -o out.png` (quick sizes) in a folder holding
/// `files` and asserts a clean input error: exit code 2, one `error:` line containing every
/// `needle`, no panic, and no file written besides `files`.
fn assert_input_error(small: &Path, main: &Path, files: &[(&str, &[u8])], needles: &[&str]) {
    let dir = tempfile::tempdir().unwrap();
    for (name, bytes) in files {
        std::fs::write(dir.path().join(name), bytes).unwrap();
    }
    let mut args = vec!["--small", small.to_str().unwrap(), "--main", main.to_str().unwrap(), "-o", "out.png"];
    args.extend(SMALL_RUN);
    let out = texture(&args, dir.path());
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.starts_with("error: "), "{err}");
    assert!(!err.contains("panicked"), "{err}");
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    for n in needles {
        assert!(err.contains(n), "{n:?} not in {err}");
    }
    let written = std::fs::read_dir(dir.path()).unwrap().count();
    assert_eq!(written, files.len(), "files written besides the inputs");
}

/// A PNG of `w × h` pixels made by `f`.
fn png(w: u32, h: u32, f: impl Fn(u32, u32) -> [u8; 3]) -> Vec<u8> {
    let img = image::RgbImage::from_fn(w, h, |i, j| image::Rgb(f(i, j)));
    let mut bytes = Vec::new();
    img.write_to(&mut std::io::Cursor::new(&mut bytes), image::ImageFormat::Png).unwrap();
    bytes
}

#[test]
fn missing_file() {
    assert_input_error(
        Path::new("nope.png"),
        &example("main-structure.png"),
        &[],
        &["--small", "nope.png", "cannot read"],
    );
}

#[test]
fn unsupported_format() {
    // A text file, a GIF (a real image format that is not PNG or JPEG), and a corrupt PNG.
    assert_input_error(
        Path::new("waves.txt"),
        &example("main-structure.png"),
        &[("waves.txt", b"not an image at all\n")],
        &["--small", "waves.txt", "unsupported image format (expected PNG or JPEG)"],
    );
    // The header of a 1×1 GIF: recognised by its signature, not decoded (GIF is not enabled).
    let gif: &[u8] = b"GIF89a\x01\x00\x01\x00\x00\x00\x00;";
    assert_input_error(
        &example("small-waves.png"),
        Path::new("main.gif"),
        &[("main.gif", gif)],
        &["--main", "main.gif", "unsupported image", "PNG or JPEG"],
    );
    assert_input_error(
        Path::new("waves.png"),
        &example("main-structure.png"),
        &[("waves.png", b"not a PNG\n")],
        &["--small", "waves.png", "cannot decode", "Invalid PNG signature"],
    );
}

#[test]
fn image_smaller_than_the_patch() {
    let tiny = png(20, 30, |i, j| [(i * 9) as u8, (j * 7) as u8, 100]);
    assert_input_error(
        Path::new("tiny.png"),
        &example("main-structure.png"),
        &[("tiny.png", &tiny)],
        &["tiny.png", "20×30 px", "smaller than the patch size 24 px"],
    );
}

#[test]
fn uniform_image() {
    let grey = png(80, 80, |_, _| [90, 90, 90]);
    assert_input_error(
        &example("small-waves.png"),
        Path::new("grey.png"),
        &[("grey.png", &grey)],
        &["grey.png", "uniform intensity", "I_max = I_min"],
    );
}

#[test]
fn same_seed_same_bytes_and_another_seed_differs() {
    let dir = tempfile::tempdir().unwrap();
    let (small, main) = (example("small-waves.png"), example("main-structure.png"));
    let run = |seed: &str, out: &str| {
        let mut args = vec!["--small", small.to_str().unwrap(), "--main", main.to_str().unwrap(), "-o", out];
        args.extend(["--seed", seed, "--frames", "5..7", "-q"]);
        args.extend(SMALL_RUN);
        let o = texture(&args, dir.path());
        assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    };
    run("7", "a_#.png");
    run("7", "b_#.png");
    run("8", "c_#.png");
    let read = |name: &str| std::fs::read(dir.path().join(name)).unwrap();
    for f in [5, 6] {
        assert_eq!(read(&format!("a_{f}.png")), read(&format!("b_{f}.png")), "frame {f} differs for the same seed");
    }
    assert_ne!(read("a_6.png"), read("c_6.png"), "another seed gives the same frame");
    // Frames are colour images of photos: tagged sRGB, as the renderer's.
    let frame = png::Decoder::new(std::io::Cursor::new(read("a_5.png"))).read_info().unwrap();
    assert_eq!(frame.info().srgb, Some(png::SrgbRenderingIntent::Perceptual));
}

/// `--dump`'s textures are colour images, tagged sRGB; its height fields are 16-bit data,
/// untagged.
#[test]
fn dumped_textures_are_tagged_and_height_fields_are_not() {
    let dir = tempfile::tempdir().unwrap();
    let (small, main) = (example("small-waves.png"), example("main-structure.png"));
    let mut args = vec!["--small", small.to_str().unwrap(), "--main", main.to_str().unwrap(), "-o", "f.png"];
    args.extend(["--dump", "dump", "-q"]);
    args.extend(SMALL_RUN);
    let o = texture(&args, dir.path());
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let info = |name: &str| {
        let bytes = std::fs::read(dir.path().join("dump").join(name)).unwrap();
        let r = png::Decoder::new(std::io::Cursor::new(bytes)).read_info().unwrap();
        (r.info().srgb, r.info().bit_depth, r.info().color_type)
    };
    for name in ["main-texture.png", "small-frame-00.png"] {
        assert_eq!(info(name), (Some(png::SrgbRenderingIntent::Perceptual), png::BitDepth::Eight, png::ColorType::Rgb));
    }
    for name in ["main-height.png", "small-height-00.png"] {
        assert_eq!(info(name), (None, png::BitDepth::Sixteen, png::ColorType::Grayscale));
    }
}
