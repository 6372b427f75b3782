//! Scripted input for the preview window: what its tests (and a user recording a demo) play
//! instead of a hand on the mouse.
//!
//! One command per line; `#` starts a comment:
//!
//! | command | effect |
//! |---|---|
//! | `wait S` | wait S seconds |
//! | `settle` | wait until the view on screen is fully refined |
//! | `drag DX DY [S] [right]` | drag over the image by (DX, DY) points in S seconds (0.5), with the left (orbit) or right (pan) button |
//! | `scroll DY` | scroll over the image by DY points (zoom) |
//! | `screenshot FILE` | write the window as a PNG |
//! | `save FILE` | save the scene as TOML (the "save" button) |
//! | `render` | render the output image (the "render" button) and wait for it |
//! | `quit` | close the window |

use std::path::PathBuf;

/// One step of a script.
#[derive(Debug, Clone, PartialEq)]
pub enum Step {
    /// Wait this many seconds.
    Wait(f64),
    /// Wait until the view is fully refined.
    Settle,
    /// Drag over the image by `(dx, dy)` points in `seconds`, with the right button if `pan`.
    Drag {
        /// Horizontal distance (points).
        dx: f32,
        /// Vertical distance (points, down positive).
        dy: f32,
        /// Duration (s).
        seconds: f64,
        /// The right button (pan) instead of the left (orbit).
        pan: bool,
    },
    /// Scroll by this many points (positive: up, zoom in).
    Scroll(f32),
    /// Write the window to a PNG.
    Screenshot(PathBuf),
    /// Save the scene as TOML.
    Save(PathBuf),
    /// Render the output image and wait for it.
    Render,
    /// Close the window.
    Quit,
}

/// Parses a script; errors name the line and what was expected.
///
/// # Errors
/// A message `line N: ...` for the first line that is not a command.
pub fn parse(text: &str) -> Result<Vec<Step>, String> {
    let mut steps = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let line = raw.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let err = |what: &str| format!("line {}: {what} (in `{line}`)", i + 1);
        let words: Vec<&str> = line.split_whitespace().collect();
        let number = |k: usize, name: &str| -> Result<f64, String> {
            words
                .get(k)
                .ok_or_else(|| err(&format!("{name} is missing")))?
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| err(&format!("{name} must be a number")))
        };
        let path = |name: &str| -> Result<PathBuf, String> {
            words.get(1).map(PathBuf::from).ok_or_else(|| err(&format!("{name} is missing")))
        };
        steps.push(match words[0] {
            "wait" => Step::Wait(number(1, "the seconds")?.max(0.0)),
            "settle" => Step::Settle,
            "drag" => {
                let seconds = if words.len() > 3 && words[3] != "right" { number(3, "the seconds")? } else { 0.5 };
                Step::Drag {
                    dx: number(1, "DX")? as f32,
                    dy: number(2, "DY")? as f32,
                    seconds: seconds.max(0.0),
                    pan: words.last() == Some(&"right"),
                }
            }
            "scroll" => Step::Scroll(number(1, "DY")? as f32),
            "screenshot" => Step::Screenshot(path("the file")?),
            "save" => Step::Save(path("the file")?),
            "render" => Step::Render,
            "quit" => Step::Quit,
            other => {
                return Err(err(&format!(
                    "unknown command `{other}` (expected wait, settle, drag, scroll, screenshot, save, render or quit)"
                )));
            }
        });
    }
    Ok(steps)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scripts_parse_and_bad_lines_name_themselves() {
        let steps = parse(
            "wait 0.5 # first image\nsettle\n\ndrag 10 -4 2 right\ndrag 3 4\nscroll -120\nscreenshot a.png\nrender\nquit",
        )
        .unwrap();
        assert_eq!(
            steps,
            vec![
                Step::Wait(0.5),
                Step::Settle,
                Step::Drag { dx: 10.0, dy: -4.0, seconds: 2.0, pan: true },
                Step::Drag { dx: 3.0, dy: 4.0, seconds: 0.5, pan: false },
                Step::Scroll(-120.0),
                Step::Screenshot("a.png".into()),
                Step::Render,
                Step::Quit,
            ]
        );
        let e = parse("wait 1\njump 3").unwrap_err();
        assert!(e.starts_with("line 2:") && e.contains("jump"), "{e}");
        let e = parse("drag 1 x").unwrap_err();
        assert!(e.contains("DY must be a number"), "{e}");
    }
}
