//! The published data tables embedded in the crate (`data/*.csv`), parsed once on first use.
//!
//! Each table is on a uniform wavelength grid; [`Table::at`] interpolates linearly between its
//! rows and returns the published value exactly at a tabulated wavelength.

use std::sync::OnceLock;

/// A table of columns sampled on a uniform wavelength grid.
#[derive(Debug)]
pub(crate) struct Table {
    /// First tabulated wavelength (nm).
    pub start_nm: f64,
    /// Grid step (nm).
    pub step_nm: f64,
    /// Column names (after the wavelength).
    pub names: Vec<String>,
    /// `columns[j][i]`: column `j` at row `i`.
    pub columns: Vec<Vec<f64>>,
}

impl Table {
    /// Parses a CSV with `#` comment lines, one header line, a wavelength column then values.
    ///
    /// Panics on a malformed embedded file: the files are part of the crate and a test parses
    /// each of them, so this never happens on user input.
    fn parse(text: &str) -> Self {
        let mut lines = text.lines().map(str::trim).filter(|l| !l.is_empty() && !l.starts_with('#'));
        let header = lines.next().expect("embedded table has a header");
        let names: Vec<String> = header.split(',').skip(1).map(str::to_owned).collect();
        let mut wavelengths = Vec::new();
        let mut columns = vec![Vec::new(); names.len()];
        for line in lines {
            let mut fields = line.split(',').map(|f| f.trim().parse::<f64>().expect("embedded table value"));
            wavelengths.push(fields.next().expect("wavelength"));
            for column in &mut columns {
                column.push(fields.next().expect("value"));
            }
        }
        let start_nm = wavelengths[0];
        let step_nm = wavelengths[1] - wavelengths[0];
        for (i, w) in wavelengths.iter().enumerate() {
            assert!((w - (start_nm + step_nm * i as f64)).abs() < 1e-9, "embedded table grid is not uniform");
        }
        Self { start_nm, step_nm, names, columns }
    }

    /// Last tabulated wavelength (nm).
    #[cfg(test)]
    pub fn end_nm(&self) -> f64 {
        self.start_nm + self.step_nm * (self.columns[0].len() - 1) as f64
    }

    /// Column `j` at `lambda_nm`, linearly interpolated; clamped to the table's range.
    #[inline]
    pub fn at(&self, j: usize, lambda_nm: f64) -> f64 {
        let col = &self.columns[j];
        let x = ((lambda_nm - self.start_nm) / self.step_nm).clamp(0.0, (col.len() - 1) as f64);
        let i = (x.floor() as usize).min(col.len() - 2);
        let t = x - i as f64;
        if t == 0.0 { col[i] } else { col[i] + t * (col[i + 1] - col[i]) }
    }

    /// Index of column `name`.
    pub fn column(&self, name: &str) -> usize {
        self.names.iter().position(|n| n == name).expect("known column")
    }
}

/// Pope & Fry (1997) pure-water absorption, 380–700 nm.
pub(crate) fn pope_fry() -> &'static Table {
    static T: OnceLock<Table> = OnceLock::new();
    T.get_or_init(|| Table::parse(POPE_FRY_CSV))
}

/// Morel (1988) `K_w`, `χ`, `e` and `b_w`, 400–700 nm.
pub(crate) fn morel() -> &'static Table {
    static T: OnceLock<Table> = OnceLock::new();
    T.get_or_init(|| Table::parse(MOREL_CSV))
}

/// Prieur & Sathyendranath (1981) normalised chlorophyll absorption, 400–700 nm.
pub(crate) fn prieur_sathyendranath() -> &'static Table {
    static T: OnceLock<Table> = OnceLock::new();
    T.get_or_init(|| Table::parse(PRIEUR_SATHYENDRANATH_CSV))
}

/// Jerlov (1976) `K_d` of the water types, 350–700 nm.
pub(crate) fn jerlov() -> &'static Table {
    static T: OnceLock<Table> = OnceLock::new();
    T.get_or_init(|| Table::parse(JERLOV_CSV))
}

/// `data/pope_fry_1997_pure_water_absorption.csv`.
pub(crate) const POPE_FRY_CSV: &str = include_str!("../data/pope_fry_1997_pure_water_absorption.csv");
/// `data/morel_1988_kd.csv`.
pub(crate) const MOREL_CSV: &str = include_str!("../data/morel_1988_kd.csv");
/// `data/prieur_sathyendranath_1981_chl_absorption.csv`.
pub(crate) const PRIEUR_SATHYENDRANATH_CSV: &str =
    include_str!("../data/prieur_sathyendranath_1981_chl_absorption.csv");
/// `data/jerlov_1976_kd.csv`.
pub(crate) const JERLOV_CSV: &str = include_str!("../data/jerlov_1976_kd.csv");

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    #[expect(clippy::float_cmp, reason = "tabulated values are returned exactly")]
    fn tables_parse_and_interpolate_exactly_at_rows() {
        let t = pope_fry();
        assert_eq!(t.columns[0].len(), 129);
        assert_eq!(t.at(0, 450.0), 0.00922);
        assert_eq!(t.end_nm(), 700.0);
        /// One rounding of the interpolation.
        const ROUNDING: f64 = 1e-15;
        assert!((t.at(0, 451.25) - 0.5 * (0.00922 + 0.00969)).abs() < ROUNDING);
        assert_eq!(morel().columns.len(), 4);
        assert_eq!(morel().columns[0].len(), 61);
        assert_eq!(prieur_sathyendranath().columns[0].len(), 61);
        assert_eq!(jerlov().columns.len(), 10);
        assert_eq!(jerlov().start_nm, 350.0);
    }
}
