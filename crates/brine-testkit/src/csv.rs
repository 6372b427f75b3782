//! The records of the embedded reference tables (comma-separated, `#` comments, one header line).

/// The records of `text`: blank lines and lines starting with `#` are skipped, the first line
/// left is the header (dropped), and every other line is split at commas into trimmed fields.
pub fn records(text: &str) -> Vec<Vec<&str>> {
    text.lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .skip(1)
        .map(|l| l.split(',').map(str::trim).collect())
        .collect()
}

/// The records of an all-numeric table, each field parsed as `f64`.
///
/// # Panics
/// On a field that is not a number, naming the record and the field.
pub fn numbers(text: &str) -> Vec<Vec<f64>> {
    records(text)
        .iter()
        .enumerate()
        .map(|(r, fields)| {
            fields
                .iter()
                .map(|f| f.parse().unwrap_or_else(|e| panic!("record {r}: field {f:?} is not a number ({e})")))
                .collect()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn comments_blank_lines_and_the_header_are_skipped() {
        let text = "# a table\nx,y\n\n1, 2\n# more\n3,4.5\n";
        assert_eq!(records(text), vec![vec!["1", "2"], vec!["3", "4.5"]]);
        assert_eq!(numbers(text), vec![vec![1.0, 2.0], vec![3.0, 4.5]]);
    }
}
