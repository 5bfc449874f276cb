//! The body against measured people: ANSUR II's two reaches taken on the
//! model as the survey took them on each person (docs/calibration.md).
//!
//! - Thumb-tip reach: standing, back and shoulders against a wall, the arm
//!   straight forward at shoulder height, the thumb's tip pinched against
//!   the index finger; the wall to the thumb's tip. On the model: the trunk
//!   upright, shoulder flexion 90 deg and every other joint of the arm at
//!   zero (the girdle down); the wall touches the rearmost solid of the
//!   body; the distance runs to the `thumb_tip` effector.
//! - Overhead fingertip reach, sitting: sitting erect, the arm stretched
//!   straight up; the seat to the tip of the middle finger. On the model:
//!   the trunk upright, shoulder flexion 180 deg, the girdle as high as
//!   its rhythm lets it rise, the rest at zero; the `fingertip` effector's
//!   height above the seat (the legs' `hip_above_seat` below the hip
//!   point).
//!
//! A person is built from a survey row as `std::populations` builds one:
//! by `ansur_adult` with the row's measurements.

use nalgebra::Point3;

use crate::ansur::survey;
use crate::kinematics::{Body, Chain};
use crate::plugin::Registry;
use crate::{Diagnostics, Input};

/// The two reaches of a body, in millimetres.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Reaches {
    pub thumb_tip_mm: f64,
    pub overhead_mm: f64,
}

/// What a body lacks to be measured as ANSUR measured people.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Unmeasurable {
    /// No effector of this name (`thumb_tip`, `fingertip`).
    Effector(&'static str),
    /// No joint of this name on that effector's chain.
    Joint(&'static str),
    /// No legs, so no seat below the hip point.
    Legs,
}

/// The shoulder joint that raises the arm forwards.
const FLEXION: &str = "shoulder_flexion";
/// The girdle's slide up the trunk.
const GIRDLE: &str = "shoulder_elevation";

/// ANSUR II's thumb-tip and seated overhead fingertip reach, taken on
/// `body` (std::body's joint and effector names).
pub fn reaches(body: &Body) -> Result<Reaches, Unmeasurable> {
    let thumb = chain(body, "thumb_tip")?;
    let mut q = vec![0.0; thumb.dof()];
    q[joint(&thumb, FLEXION)?] = 90f64.to_radians();
    let tip = thumb.effector(&q);
    let volumes = thumb.volumes(&q);
    let wall_mm = volumes
        .capsules
        .iter()
        .map(|c| c.a.x.min(c.b.x) - c.radius_mm)
        .fold(f64::INFINITY, f64::min);

    let finger = chain(body, "fingertip")?;
    let mut q = vec![0.0; finger.dof()];
    q[joint(&finger, FLEXION)?] = 180f64.to_radians();
    if let Ok(girdle) = joint(&finger, GIRDLE) {
        q[girdle] = finger.joints[girdle].max;
        finger.pull_in(&mut q);
    }
    let seat_below_hip_mm = body
        .legs
        .as_ref()
        .ok_or(Unmeasurable::Legs)?
        .hip_above_seat_mm;
    let top: Point3<f64> = finger.effector(&q);
    Ok(Reaches {
        thumb_tip_mm: tip.x - wall_mm,
        overhead_mm: top.z + seat_below_hip_mm,
    })
}

fn chain(body: &Body, effector: &'static str) -> Result<Chain, Unmeasurable> {
    body.chain_named(Some(effector))
        .ok_or(Unmeasurable::Effector(effector))
}

fn joint(chain: &Chain, name: &'static str) -> Result<usize, Unmeasurable> {
    chain
        .joints
        .iter()
        .position(|j| j.name == name)
        .ok_or(Unmeasurable::Joint(name))
}

/// The measurements `ansur_adult` takes, by their survey column names.
pub const COLUMNS: [&str; 18] = [
    "stature",
    "sittingheight",
    "eyeheightsitting",
    "acromialheight",
    "biacromialbreadth",
    "shoulderelbowlength",
    "forearmhandlength",
    "handlength",
    "chestdepth",
    "bicepscircumferenceflexed",
    "forearmcircumferenceflexed",
    "wristcircumference",
    "neckcircumference",
    "headbreadth",
    "headlength",
    "hipbreadthsitting",
    "thighclearance",
    "calfcircumference",
];

/// `ansur_adult(...)` with survey row `row`'s measurements.
pub fn mannequin_of(row: usize) -> String {
    let rows = survey();
    let measured = &rows.rows[row];
    let args: Vec<String> = COLUMNS
        .iter()
        .map(|c| {
            let i = rows.columns.iter().position(|n| n == c);
            let v = i.map_or(f64::NAN, |i| measured.lengths_mm[i]);
            format!("{c} {v}mm")
        })
        .collect();
    format!("ansur_adult({})", args.join(", "))
}

/// The bodies of survey rows `rows`, each built as `std::populations`
/// builds a person of that row (by `ansur_adult`), in their order.
pub fn bodies(rows: &[usize]) -> Result<Vec<Body>, Diagnostics> {
    let mut text = String::from("use std::populations\n");
    for (k, &row) in rows.iter().enumerate() {
        text += &format!(
            "person r{k} {{ mannequin {} base fixed {{ at (0, 0, 0) }} }}\n",
            mannequin_of(row)
        );
    }
    let input = Input::Text {
        name: "calibration.reach",
        text: &text,
    };
    let (_, checked) = crate::check(input, &Registry::builtin());
    checked.map(|s| s.persons.into_iter().map(|p| p.body).collect())
}

/// std::people's percentile people: name, whether a woman, and the
/// percentile of their sex they stand for.
pub const PERCENTILE_PEOPLE: [(&str, bool, f64); 3] = [
    ("woman_5th", true, 5.0),
    ("man_50th", false, 50.0),
    ("man_95th", false, 95.0),
];

/// Survey column `column` of the women (or the men).
pub fn of_sex(column: &str, female: bool) -> Vec<f64> {
    let rows = survey();
    let Some(i) = rows.columns.iter().position(|c| c == column) else {
        return Vec::new();
    };
    rows.rows
        .iter()
        .filter(|m| m.female == female)
        .map(|m| m.lengths_mm[i])
        .collect()
}

/// The standard deviation of `values` (of the values themselves, not an
/// estimate for a population they are drawn from).
pub fn standard_deviation(values: &[f64]) -> f64 {
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    (values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n).sqrt()
}

/// The `p`-th percentile (0-100) of `values`, by the nearest rank of the
/// sorted values (NaN where there are none).
pub fn percentile(values: &[f64], p: f64) -> f64 {
    let mut sorted: Vec<f64> = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    if sorted.is_empty() {
        return f64::NAN;
    }
    let rank = (p / 100.0 * (sorted.len() - 1) as f64).round() as usize;
    sorted[rank.min(sorted.len() - 1)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn percentiles_take_the_nearest_rank() {
        let v = [5.0, 1.0, 4.0, 2.0, 3.0];
        assert_eq!(percentile(&v, 50.0), 3.0);
        assert_eq!(percentile(&v, 0.0), 1.0);
        assert_eq!(percentile(&v, 100.0), 5.0);
        assert_eq!(percentile(&v, 90.0), 5.0);
        assert!(percentile(&[], 50.0).is_nan());
        assert_eq!(
            standard_deviation(&[2.0, 4.0, 4.0, 4.0, 5.0, 5.0, 7.0, 9.0]),
            2.0
        );
    }
}
