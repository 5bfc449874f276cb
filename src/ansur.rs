//! The measured adults of ANSUR II (Gordon et al., *2012 Anthropometric
//! Survey of U.S. Army Personnel*, public-release data): 1,986 women and
//! 4,082 men aged 17-58, one row each, embedded from
//! `stdlib/data/ansur2.csv`. A population draws whole rows, which keeps
//! each person's measurements together (a tall person has long arms).

use std::sync::LazyLock;

/// One measured adult: lengths in millimetres, in the order of
/// [`Survey::columns`].
#[derive(Clone, Debug, PartialEq)]
pub struct Measured {
    pub female: bool,
    pub age_years: f64,
    pub lengths_mm: Vec<f64>,
}

/// The survey: the names of its length measurements and its rows.
#[derive(Debug)]
pub struct Survey {
    /// The CSV's column names (`stature`, `eyeheightsitting`, ...).
    pub columns: Vec<String>,
    pub rows: Vec<Measured>,
}

const CSV: &str = include_str!("../stdlib/data/ansur2.csv");

/// Columns that are not lengths in millimetres.
const NOT_LENGTHS: [&str; 4] = ["Gender", "Age", "WritingPreference", "weightkg"];

/// The survey, read once.
pub fn survey() -> &'static Survey {
    static SURVEY: LazyLock<Survey> = LazyLock::new(|| read(CSV));
    &SURVEY
}

/// The survey in `csv` (a header line, then one row a person). The text is
/// the crate's own: a malformed row is a bug, caught by the tests.
fn read(csv: &str) -> Survey {
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap_or_default().split(',').collect();
    let at = |name: &str| header.iter().position(|h| *h == name);
    let (gender, age) = (at("Gender"), at("Age"));
    let lengths: Vec<usize> = (0..header.len())
        .filter(|&i| !NOT_LENGTHS.contains(&header[i]))
        .collect();
    let rows = lines
        .filter(|l| !l.trim().is_empty())
        .map(|line| {
            let cells: Vec<&str> = line.split(',').collect();
            let number = |i: usize| cells.get(i).and_then(|c| c.trim().parse().ok());
            Measured {
                female: gender.and_then(|i| cells.get(i)) == Some(&"Female"),
                age_years: age.and_then(number).unwrap_or(f64::NAN),
                lengths_mm: lengths
                    .iter()
                    .map(|&i| number(i).unwrap_or(f64::NAN))
                    .collect(),
            }
        })
        .collect();
    Survey {
        columns: lengths.iter().map(|&i| header[i].to_string()).collect(),
        rows,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_row_is_whole_and_the_counts_are_the_survey_s() {
        let s = survey();
        assert_eq!(s.rows.len(), 6068);
        assert_eq!(s.rows.iter().filter(|r| r.female).count(), 1986);
        for r in &s.rows {
            assert_eq!(r.lengths_mm.len(), s.columns.len());
            assert!(r.lengths_mm.iter().all(|v| v.is_finite() && *v > 0.0));
            assert!((17.0..=58.0).contains(&r.age_years));
        }
    }

    #[test]
    fn median_statures_are_those_of_the_reference_table() {
        let s = survey();
        let stature = s.columns.iter().position(|c| c == "stature").unwrap();
        let median = |female: bool| {
            let mut v: Vec<f64> = s
                .rows
                .iter()
                .filter(|r| r.female == female)
                .map(|r| r.lengths_mm[stature])
                .collect();
            v.sort_by(f64::total_cmp);
            v[v.len() / 2]
        };
        // docs/references.md: women 1626, men 1755 mm (50th percentile).
        assert!((median(true) - 1626.0).abs() <= 3.0, "{}", median(true));
        assert!((median(false) - 1755.0).abs() <= 3.0, "{}", median(false));
    }
}
