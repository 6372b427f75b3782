//! The raw check of a scene file against the key table, on the parsed TOML with its spans: every
//! key known, every value of its type and in its range, and the line of every key for messages
//! (dotted keys, inline tables and quoted keys included).

use toml::Spanned;
use toml::de::{DeTable, DeValue};

use super::keys::{self, KeySpec, Kind, SECTIONS};

/// A problem found in the raw table: the byte offset of the offending key, when known, and the
/// message.
pub(super) type RawError = (Option<usize>, String);

/// A TOML syntax error: where it is and what the parser says, with the key it points at when the
/// parser names none (its "duplicate key" leaves the reader to find which).
pub(super) fn syntax_error(text: &str, e: &toml::de::Error) -> RawError {
    let message = e.message().trim();
    let at = e.span();
    let named =
        at.as_ref().and_then(|s| text.get(s.clone())).map(str::trim).filter(|k| !k.is_empty() && !k.contains('\n'));
    let message = match named {
        Some(key) if message == "duplicate key" => format!(
            "duplicate key `{key}`: a key is set once in its table, and a table is opened once (by one `[header]` or by dotted keys, not both)"
        ),
        _ => message.to_owned(),
    };
    (at.map(|s| s.start), format!("invalid TOML: {message}"))
}

/// The parsed document, for finding the line of a key after the scene structs are checked.
pub(super) struct Located<'a> {
    root: DeTable<'a>,
}

impl<'a> Located<'a> {
    /// Parses `text` (a UTF-8 byte-order mark already removed).
    pub(super) fn parse(text: &'a str) -> Result<Self, RawError> {
        let doc = DeTable::parse(text).map_err(|e| syntax_error(text, &e))?;
        Ok(Self { root: doc.into_inner() })
    }

    /// Byte offset of the key `path` (dotted, `sea.swell.waves`) if the file sets it; for a
    /// section, of its header.
    pub(super) fn offset_of(&self, path: &str) -> Option<usize> {
        let mut table = &self.root;
        let parts: Vec<&str> = path.split('.').collect();
        for (i, part) in parts.iter().enumerate() {
            let (key, value) = table.get_key_value(*part)?;
            if i + 1 == parts.len() {
                return Some(key.span().start);
            }
            match value.get_ref() {
                DeValue::Table(t) => table = t,
                _ => return Some(key.span().start),
            }
        }
        None
    }

    /// Checks every key of the document against the key table.
    pub(super) fn check(&self) -> Result<(), RawError> {
        check_table(&self.root, "")
    }
}

fn check_table(table: &DeTable<'_>, prefix: &str) -> Result<(), RawError> {
    for (key, value) in table {
        let name = key.get_ref().as_ref();
        let path = if prefix.is_empty() { name.to_owned() } else { format!("{prefix}.{name}") };
        let at = Some(key.span().start);
        if SECTIONS.contains(&path.as_str()) {
            match value.get_ref() {
                DeValue::Table(t) => check_table(t, &path)?,
                DeValue::Array(_) => {
                    return Err((
                        at,
                        format!("{path} is a section: write it once as [{path}], not as an array of tables [[{path}]]"),
                    ));
                }
                other => {
                    return Err((
                        at,
                        format!(
                            "{path} is a section: expected a table ([{path}] or {path} = {{ … }}), found {}",
                            describe(other)
                        ),
                    ));
                }
            }
            continue;
        }
        match keys::find(prefix, name) {
            Some(spec) => check_value(spec, value).map_err(|m| (at, m))?,
            None => return Err((at, unknown(prefix, name))),
        }
    }
    Ok(())
}

/// The message of an unknown key, listing what the section accepts.
fn unknown(section: &str, name: &str) -> String {
    let mut expected: Vec<String> =
        keys::KEYS.iter().filter(|s| s.section == section).map(|s| s.key.to_owned()).collect();
    let depth = if section.is_empty() { 0 } else { section.split('.').count() };
    for s in SECTIONS {
        let parts: Vec<&str> = s.split('.').collect();
        if parts.len() == depth + 1 && (section.is_empty() || s.starts_with(&format!("{section}."))) {
            expected.push(format!("[{s}]"));
        }
    }
    let path = if section.is_empty() { name.to_owned() } else { format!("{section}.{name}") };
    format!("unknown key {path} (expected one of {})", expected.join(", "))
}

/// What a value is, in words, for messages.
fn describe(v: &DeValue<'_>) -> String {
    match v {
        DeValue::String(s) => format!("string {s:?}"),
        DeValue::Integer(i) => format!("integer {}", i.as_str()),
        DeValue::Float(f) => format!("float {}", f.as_str()),
        DeValue::Boolean(b) => format!("boolean {b}"),
        DeValue::Datetime(d) => format!("date-time {d}"),
        DeValue::Array(a) => format!("an array of {} elements", a.len()),
        DeValue::Table(_) => "a table".to_owned(),
    }
}

/// A TOML number as f64 (integers included); `None` for other types.
fn number(v: &DeValue<'_>) -> Option<f64> {
    match v {
        DeValue::Integer(i) => integer(v).map(|n| n as f64).or_else(|| i.as_str().parse().ok()),
        DeValue::Float(f) => {
            let s = f.as_str().replace('_', "");
            let (sign, body) = match s.strip_prefix('-') {
                Some(b) => (-1.0, b.to_owned()),
                None => (1.0, s.strip_prefix('+').unwrap_or(&s).to_owned()),
            };
            body.parse::<f64>().ok().map(|x| sign * x)
        }
        _ => None,
    }
}

/// A TOML integer as i128; `None` for other types.
fn integer(v: &DeValue<'_>) -> Option<i128> {
    match v {
        DeValue::Integer(i) => {
            let s = i.as_str().replace('_', "");
            let (neg, body) = match s.strip_prefix('-') {
                Some(b) => (true, b.to_owned()),
                None => (false, s.strip_prefix('+').unwrap_or(&s).to_owned()),
            };
            i128::from_str_radix(&body, i.radix()).ok().map(|n| if neg { -n } else { n })
        }
        _ => None,
    }
}

fn in_float_range(kind: Kind, x: f64) -> bool {
    let Kind::Float { lo, hi } = kind else { return false };
    x.is_finite()
        && lo.is_none_or(|(l, inc)| if inc { x >= l } else { x > l })
        && hi.is_none_or(|(h, inc)| if inc { x <= h } else { x < h })
}

/// Checks one value against its spec.
fn check_value(spec: &KeySpec, value: &Spanned<DeValue<'_>>) -> Result<(), String> {
    let v = value.get_ref();
    let path = spec.path();
    let expected = spec.expected();
    let wrong_type = || format!("expected {expected} for {path}, found {}", describe(v));
    let out_of_range = |shown: &dyn std::fmt::Display| format!("{path} = {shown} is out of range: expected {expected}");
    match spec.kind {
        Kind::Float { .. } => {
            let x = number(v).ok_or_else(|| format!("expected a number for {path}, found {}", describe(v)))?;
            if !in_float_range(spec.kind, x) {
                return Err(out_of_range(&x));
            }
        }
        Kind::Int { lo, hi } | Kind::PowerOfTwo { lo, hi } => {
            let n = match v {
                DeValue::Integer(_) => integer(v).ok_or_else(wrong_type)?,
                DeValue::Float(_) => {
                    return Err(format!("expected a whole number for {path} ({expected}), found {}", describe(v)));
                }
                _ => return Err(format!("expected a whole number for {path}, found {}", describe(v))),
            };
            let pow2 = !matches!(spec.kind, Kind::PowerOfTwo { .. }) || (n > 0 && (n & (n - 1)) == 0);
            if n < lo || n > hi || !pow2 {
                return Err(out_of_range(&n));
            }
        }
        Kind::Bool => {
            if !matches!(v, DeValue::Boolean(_)) {
                return Err(format!("expected true or false for {path}, found {}", describe(v)));
            }
        }
        Kind::Enum { values, ignore_case } => {
            let DeValue::String(s) = v else { return Err(wrong_type()) };
            let ok = values.iter().any(|x| if ignore_case { x.eq_ignore_ascii_case(s) } else { x == s });
            if !ok {
                return Err(format!("unknown value {s:?} for {path}: expected {expected}"));
            }
        }
        Kind::Instant => {
            let DeValue::String(s) = v else { return Err(wrong_type()) };
            brine_ephem::parse_utc(s).and_then(brine_ephem::check_range).map_err(|e| format!("{path}: {e}"))?;
        }
        Kind::ImagePath => {
            let DeValue::String(s) = v else { return Err(wrong_type()) };
            crate::output::OutputFormat::from_path(std::path::Path::new(s.as_ref()))?;
        }
        Kind::FloatArray { len, lo, hi } => {
            let DeValue::Array(a) = v else { return Err(wrong_type()) };
            if a.len() != len {
                return Err(format!("{path} has {} elements: expected {expected}", a.len()));
            }
            for (i, e) in a.iter().enumerate() {
                let x = number(e.get_ref())
                    .ok_or_else(|| format!("expected a number for {path}[{i}], found {}", describe(e.get_ref())))?;
                if !(x.is_finite() && x >= lo && x <= hi) {
                    return Err(format!("{path}[{i}] = {x} is out of range: expected {expected}"));
                }
            }
        }
    }
    Ok(())
}
