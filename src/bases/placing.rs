//! How a mobile base may be placed, as its options say: the headings it
//! may face (all round, one, or a range), the approach (the target in
//! front of the person or beside them, as accessibility standards tell a
//! forward from a side approach) and the floor zone it must stay in.

use std::f64::consts::{FRAC_PI_4, PI};

use nalgebra::{Point3, Vector2, Vector3};

use crate::floor::Zone;
use crate::plugin::{BasePose, Params, SettingsError};

/// Where the target may be, seen from the person.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Approach {
    /// Anywhere.
    Any,
    /// In front: between the lines of the base's sides, and within 45
    /// degrees of the direction faced (ADA 308.2: the person faces the
    /// element).
    Forward,
    /// Beside: beyond the line of one of the base's sides, and not behind
    /// (within 135 degrees of the direction faced; ADA 308.3: the chair
    /// parallel to the element, which is beside it). A chair parallel to a
    /// wall reaching a point on it a little ahead is a side approach,
    /// however small the angle from the hip.
    Side,
}

/// A target this close inside the line of a base's side is beside it: a
/// chair against a wall stands up to two floor cells (10 mm) off it.
pub const SIDE_SLACK_MM: f64 = 10.0;

impl Approach {
    /// `any`, `forward` or `side`, as an option's value says it.
    pub fn parse(word: &str) -> Result<Self, SettingsError> {
        match word {
            "any" => Ok(Approach::Any),
            "forward" => Ok(Approach::Forward),
            "side" => Ok(Approach::Side),
            other => Err(SettingsError::invalid(
                "approach",
                format!("`{other}` is not an approach: use `forward`, `side` or `any`"),
            )),
        }
    }

    /// Whether a target at `in_base_mm` (the base frame: x ahead, y to the
    /// left) is where this approach puts it, for a base whose sides are
    /// `half_width_mm` either side of the hip point.
    pub fn admits(self, in_base_mm: &Vector3<f64>, half_width_mm: f64) -> bool {
        let off_ahead = in_base_mm.y.atan2(in_base_mm.x).abs();
        let beside = in_base_mm.y.abs() >= half_width_mm - SIDE_SLACK_MM;
        match self {
            Approach::Any => true,
            Approach::Forward => !beside && off_ahead <= FRAC_PI_4 + 1e-9,
            Approach::Side => beside && off_ahead <= 3.0 * FRAC_PI_4 + 1e-9,
        }
    }

    /// Whether a base facing `heading_rad` approaches a target on a
    /// vertical face whose outward normal is `face` (none: the target is on
    /// no face, and any heading will do) as this approach asks: facing the
    /// face to within 45 degrees for a forward approach, parallel to it to
    /// within 45 degrees for a side one (a chair at 45 degrees to the face
    /// is at neither).
    pub fn faces(self, heading_rad: f64, face: Option<Vector2<f64>>) -> bool {
        let Some(normal) = face else { return true };
        let ahead = Vector2::new(heading_rad.cos(), heading_rad.sin());
        let facing = -ahead.dot(&normal);
        match self {
            Approach::Any => true,
            Approach::Forward => facing > FRAC_PI_4.cos() + 1e-9,
            Approach::Side => facing.abs() < FRAC_PI_4.sin() - 1e-9,
        }
    }

    /// Whether the target `target_room_mm` is where this approach puts it
    /// for a base at `pose` (its sides `half_width_mm` from the hip point).
    pub fn admits_pose(
        self,
        pose: &BasePose,
        target_room_mm: &Point3<f64>,
        half_width_mm: f64,
    ) -> bool {
        self.admits(&pose.to_base(target_room_mm).coords, half_width_mm)
    }
}

/// How a mobile base is placed, checked.
#[derive(Clone, Debug, PartialEq)]
pub struct Placing {
    /// The headings searched, in radians.
    pub headings: Vec<f64>,
    pub approach: Approach,
    pub zone: Option<Zone>,
}

impl Placing {
    /// `n` headings all round, any approach, no zone.
    pub fn all_round(n: u32) -> Self {
        Placing {
            headings: (0..n.max(1))
                .map(|k| 2.0 * PI * f64::from(k) / f64::from(n.max(1)))
                .collect(),
            approach: Approach::Any,
            zone: None,
        }
    }
}

/// The placing options every mobile base shares, as given.
#[derive(Clone, Debug, PartialEq)]
pub struct PlacingSettings {
    pub headings: u32,
    pub heading_rad: Option<f64>,
    pub heading_within_rad: Option<f64>,
    pub approach: String,
    pub zone_mm: [Option<Vector3<f64>>; 2],
    /// `zone`: an outline's corners, in order (z left out).
    pub zone_outline_mm: Option<Vec<Vector3<f64>>>,
}

impl PlacingSettings {
    /// The placing options, declared or read; `zone_doc` says who stays in
    /// the zone.
    pub fn visit(p: &mut Params<'_>, zone_doc: &'static str) -> Self {
        PlacingSettings {
            headings: p
                .integer(
                    "headings",
                    16,
                    "headings tried (all round, or over `heading_within` of `heading`)",
                )
                .range(1.0, 360.0)
                .get() as u32,
            heading_rad: p
                .optional_angle(
                    "heading",
                    "the one direction faced (0: along the room's x axis, 90deg: along y)",
                )
                .get(),
            heading_within_rad: p
                .optional_angle(
                    "heading_within",
                    "with `heading`: any heading this far either side of it",
                )
                .range(0.0, PI)
                .get(),
            approach: p
                .name(
                    "approach",
                    "any",
                    "`forward` (the target ahead, within 45deg), `side` (beside, 45-135deg) or `any`",
                )
                .get(),
            zone_mm: [
                p.optional_point("zone_from", zone_doc).get(),
                p.optional_point("zone_to", "the opposite corner").get(),
            ],
            zone_outline_mm: p
                .optional_points(
                    "zone",
                    "instead of `zone_from` and `zone_to`: the outline the hip point stays within, its corners in order",
                )
                .get(),
        }
    }

    /// The placing these options ask for, or what is wrong with them.
    pub fn placing(&self) -> Result<Placing, SettingsError> {
        Ok(Placing {
            headings: self.heading_list()?,
            approach: Approach::parse(&self.approach)?,
            zone: match &self.zone_outline_mm {
                None => zone(self.zone_mm)?,
                Some(_) if self.zone_mm != [None, None] => {
                    return Err(SettingsError::invalid(
                        "zone",
                        "give a zone as an outline (`zone`) or as two corners (`zone_from`, `zone_to`), not both",
                    ))
                }
                Some(corners) => Some(outline(corners)?),
            },
        })
    }

    /// The headings searched: `headings` all round; the one `heading`; or
    /// `headings` evenly over `heading` plus or minus `heading_within`.
    pub fn heading_list(&self) -> Result<Vec<f64>, SettingsError> {
        let n = self.headings.max(1);
        match (self.heading_rad, self.heading_within_rad) {
            (None, None) => Ok(Placing::all_round(n).headings),
            (Some(h), None) => Ok(vec![h]),
            (Some(h), Some(w)) if n == 1 || w == 0.0 => Ok(vec![h]),
            (Some(h), Some(w)) => Ok((0..n)
                .map(|k| h - w + 2.0 * w * f64::from(k) / f64::from(n - 1))
                .collect()),
            (None, Some(_)) => Err(SettingsError::invalid(
                "heading_within",
                "`heading_within` is a range about `heading`: give `heading` too",
            )),
        }
    }
}

/// The zone two corners give: both or neither must be given.
fn zone(corners: [Option<Vector3<f64>>; 2]) -> Result<Option<Zone>, SettingsError> {
    // A zone thinner than this along x or y (a point or a line, to pin
    // the hip point there) is widened to it about its middle.
    const THINNEST_MM: f64 = 1.0;
    let span = |lo: f64, hi: f64| {
        let (lo, hi) = (lo.min(hi), lo.max(hi));
        if hi - lo >= THINNEST_MM {
            (lo, hi)
        } else {
            let mid = (lo + hi) / 2.0;
            (mid - THINNEST_MM / 2.0, mid + THINNEST_MM / 2.0)
        }
    };
    match corners {
        [Some(a), Some(b)] => {
            let (x, y) = (span(a.x, b.x), span(a.y, b.y));
            Ok(Some(Zone::rectangle((x.0, y.0), (x.1, y.1))))
        }
        [None, None] => Ok(None),
        [Some(_), None] => Err(SettingsError::invalid(
            "zone_from",
            "a zone needs `zone_to` too, its opposite corner",
        )),
        [None, Some(_)] => Err(SettingsError::invalid(
            "zone_to",
            "a zone needs `zone_from` too, its opposite corner",
        )),
    }
}

/// The most corners a zone's outline may have (checking that its sides
/// do not cross costs the square of their count).
pub const MOST_ZONE_CORNERS: usize = 256;

/// The zone an outline gives: at least three corners, at most
/// [`MOST_ZONE_CORNERS`], enclosing some floor, its sides never crossing.
fn outline(corners: &[Vector3<f64>]) -> Result<Zone, SettingsError> {
    use geo::{Area, Validation};
    let bad = |message: String| Err(SettingsError::invalid("zone", message));
    if corners.len() < 3 {
        return bad(format!(
            "a zone's outline needs at least three corners; {} given",
            corners.len()
        ));
    }
    if corners.len() > MOST_ZONE_CORNERS {
        return bad(format!(
            "a zone's outline has at most {MOST_ZONE_CORNERS} corners; {} given",
            corners.len()
        ));
    }
    let ring: Vec<geo::Coord<f64>> = corners
        .iter()
        .map(|c| geo::Coord { x: c.x, y: c.y })
        .collect();
    let in_a_line = ring.windows(3).all(|w| {
        let (a, b, c) = (w[0], w[1], w[2]);
        ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)).abs() < 1e-9
    });
    let polygon = geo::Polygon::new(geo::LineString::from(ring), Vec::new());
    if in_a_line {
        return bad("a zone's outline encloses no floor: its corners are in a line".into());
    }
    if !polygon.is_valid() {
        return bad("a zone's outline crosses itself: give its corners in order round it".into());
    }
    if polygon.unsigned_area() < 1.0 {
        return bad("a zone's outline encloses less than a square millimetre of floor".into());
    }
    Zone::outline(polygon).map_or_else(|| bad("a zone's outline has no bounds".into()), Ok)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A point or a line pins the hip point there: widened to 1 mm.
    #[test]
    fn a_zone_thinner_than_a_millimetre_is_widened_to_one() {
        let at = Vector3::new(1500.0, 1500.0, 0.0);
        let z = zone([Some(at), Some(at + Vector3::new(0.0, 300.0, 0.0))])
            .unwrap()
            .unwrap();
        assert_eq!((z.min, z.max), ((1499.5, 1500.0), (1500.5, 1800.0)));
    }

    fn settings(heading: Option<f64>, within: Option<f64>, n: u32) -> PlacingSettings {
        PlacingSettings {
            headings: n,
            heading_rad: heading.map(f64::to_radians),
            heading_within_rad: within.map(f64::to_radians),
            approach: "any".into(),
            zone_mm: [None, None],
            zone_outline_mm: None,
        }
    }

    fn degrees(s: &PlacingSettings) -> Vec<f64> {
        s.heading_list()
            .unwrap()
            .iter()
            .map(|h| (h.to_degrees() * 1e6).round() / 1e6)
            .collect()
    }

    #[test]
    fn headings_all_round_one_or_a_range() {
        assert_eq!(degrees(&settings(None, None, 4)), [0.0, 90.0, 180.0, 270.0]);
        assert_eq!(degrees(&settings(Some(90.0), None, 16)), [90.0]);
        assert_eq!(
            degrees(&settings(Some(90.0), Some(30.0), 3)),
            [60.0, 90.0, 120.0]
        );
        assert!(settings(None, Some(30.0), 3).heading_list().is_err());
    }

    #[test]
    fn a_forward_approach_has_the_target_ahead_a_side_approach_beside() {
        // A chair 660 mm wide.
        let half = 330.0;
        let admits = |a: Approach, x: f64, y: f64| a.admits(&Vector3::new(x, y, 0.0), half);
        let (ahead, beside, behind) = ((500.0, -100.0), (100.0, -500.0), (-500.0, -100.0));
        assert!(admits(Approach::Forward, ahead.0, ahead.1));
        assert!(!admits(Approach::Side, ahead.0, ahead.1));
        assert!(admits(Approach::Side, beside.0, beside.1));
        assert!(!admits(Approach::Forward, beside.0, beside.1));
        assert!(!admits(Approach::Side, behind.0, behind.1));
        assert!(!admits(Approach::Forward, behind.0, behind.1));
        assert!(admits(Approach::Any, behind.0, behind.1));
        // The chair parallel to a wall on its right, its side against it,
        // a point on the wall 400 mm ahead: 39.5 deg off the heading, but
        // beside the chair, a side approach.
        assert!(admits(Approach::Side, 400.0, -330.0));
        assert!(!admits(Approach::Forward, 400.0, -330.0));
    }
}
