//! The `wheelchair` base: a seated person in a manual wheelchair. The hip
//! point is `hip_above_seat` above the seat; the chair's parts (seat,
//! backrest, rear wheels, footrests, armrests if it has them) and the
//! person's legs on it are solids the arm must stay out of, and what the
//! floor must find room for at their heights: the knees and toes go under a
//! counter as far as its knee and toe clearance allow. The chair turns with
//! the heading theta_0 (section 5.3.6 of the paper).
//!
//! Defaults from docs/references.md and the sources it
//! names: the 1991 ADA Accessibility Guidelines' large adult chair (figure
//! A3: 660 mm wide, seat 485 mm, armrests 760 mm, footrests 455 mm across);
//! the IDeA Center's measured manual seat height, 495 mm (2010); seat
//! 430 x 460 mm, backrest 420 mm above the seat and 610 mm (24 in) rear
//! wheels from Redford, Orthotics Etcetera (1986); the lower legs 20 deg
//! forward of the vertical (Kamenetz, via Panero & Zelnik 1979). Assumed:
//! the rear axle 60 mm ahead of the backrest, wheels 35 mm wide, the seat
//! and footrest boards 60 and 30 mm thick. The chair's length comes out of
//! the person's legs: 1,200 mm for the 50th-percentile man, against
//! ADA's 1,065 mm plus 150 mm of toes.

use nalgebra::Point3;

use super::placement::Mobile;
use super::PlacingSettings;
use crate::geometry::{Cuboid, Shape, Solid};
use crate::kinematics::{Legs, Stance};
use crate::plugin::{
    Base, BaseError, BasePlugin, Options, ParamSpec, Params, Plugin, Settings, SettingsError,
};
use crate::scene::Physique;

/// The plugin `wheelchair`.
pub struct Wheelchair;

/// Its settings.
#[derive(Clone, Debug, PartialEq)]
pub struct WheelchairSettings {
    pub seat_height_mm: f64,
    pub hip_above_seat_mm: Option<f64>,
    pub width_mm: f64,
    pub seat_width_mm: f64,
    pub seat_depth_mm: f64,
    pub backrest_mm: f64,
    pub wheel_mm: f64,
    pub footrest_width_mm: f64,
    pub shank_forward_rad: f64,
    pub armrests: bool,
    pub armrest_height_mm: f64,
    pub placing: PlacingSettings,
}

impl Settings for WheelchairSettings {
    fn visit(p: &mut Params<'_>) -> Self {
        WheelchairSettings {
            seat_height_mm: p
                .length("seat_height", 495.0, "seat height above the floor")
                .range(200.0, 1000.0)
                .get(),
            hip_above_seat_mm: p
                .optional_length(
                    "hip_above_seat",
                    "the hip point above the seat (default: the mannequin's legs, else 100mm)",
                )
                .range(0.0, 400.0)
                .get(),
            width_mm: p
                .length("width", 660.0, "overall width, outside the rear wheels")
                .range(300.0, 2000.0)
                .get(),
            seat_width_mm: p
                .length("seat_width", 460.0, "the seat's width")
                .range(200.0, 1000.0)
                .get(),
            seat_depth_mm: p
                .length("seat_depth", 430.0, "the seat's depth, from the backrest")
                .range(200.0, 1000.0)
                .get(),
            backrest_mm: p
                .length(
                    "backrest",
                    420.0,
                    "the backrest's height above the seat (0: none)",
                )
                .range(0.0, 1500.0)
                .get(),
            wheel_mm: p
                .length("wheel", 610.0, "the rear wheels' diameter")
                .range(100.0, 1500.0)
                .get(),
            footrest_width_mm: p
                .length("footrest_width", 455.0, "across the footrests")
                .range(100.0, 1500.0)
                .get(),
            shank_forward_rad: p
                .angle(
                    "shank_angle",
                    20f64.to_radians(),
                    "the lower legs forward of the vertical, to the footrests",
                )
                .range(0.0, 90f64.to_radians())
                .get(),
            armrests: p
                .boolean("armrests", false, "armrests at `armrest_height`")
                .get(),
            armrest_height_mm: p
                .length("armrest_height", 760.0, "the armrests' top above the floor")
                .range(200.0, 1500.0)
                .get(),
            placing: PlacingSettings::visit(
                p,
                "one corner of the floor zone the chair must stay in",
            ),
        }
    }
}

impl Plugin for Wheelchair {
    fn name(&self) -> &'static str {
        "wheelchair"
    }

    fn doc(&self) -> &'static str {
        "seated in a wheelchair: seat, backrest, wheels and footrests, the legs on it, turning with the chair"
    }

    fn params(&self) -> Vec<ParamSpec> {
        WheelchairSettings::params()
    }
}

impl BasePlugin for Wheelchair {
    fn build(&self, options: &Options, person: &Physique) -> Result<Box<dyn Base>, BaseError> {
        let s = WheelchairSettings::from_options(options)?;
        if s.width_mm < s.seat_width_mm {
            return Err(BaseError::Settings(SettingsError::invalid(
                "width",
                format!(
                    "the chair's overall width ({:.0} mm) is less than its seat's ({:.0} mm): lower `seat_width` too",
                    s.width_mm, s.seat_width_mm
                ),
            )));
        }
        if let Some(declared @ Stance::Standing) = person.posture {
            return Err(BaseError::posture("wheelchair", declared, Stance::Seated));
        }
        let chair = Chair::new(&s, person);
        let hip_height_mm = chair.hip_height_mm;
        let mut solids = chair.parts(&s);
        let legs = chair.legs.as_ref().map(|l| l.seated(s.shank_forward_rad));
        solids.extend(legs.iter().flatten().cloned());
        solids.push(match &legs {
            Some(feet) => chair.footrests(&s, feet),
            None => {
                // No legs to put them under: where ADA's chair has them.
                let half = s.footrest_width_mm / 2.0;
                chair.part("footrests", [400.0, 640.0], [-half, half], [50.0, 80.0])
            }
        });
        let pelvis = chair.legs.as_ref().map_or(0.0, |l| l.pelvis_mm);
        Ok(Box::new(Mobile::carrying(
            solids,
            person,
            pelvis,
            hip_height_mm,
            s.placing.placing()?,
        )))
    }
}

/// A chair fitted to its user. Its settings are heights above the floor;
/// its parts are made in the base frame (the hip point at the origin), so
/// each height above the floor passes through `hip_height_mm` once, where
/// a part is made (`Chair::part`).
struct Chair {
    /// The person's legs with the hip point at the chair's height above
    /// the seat.
    legs: Option<Legs>,
    /// The hip point above the floor: the seat's height and the hip's
    /// height above the seat.
    hip_height_mm: f64,
    /// The backrest's front: just behind the back of the upright trunk.
    back_x_mm: f64,
}

/// The hip point above the seat where neither chair nor mannequin says.
const HIP_ABOVE_SEAT_MM: f64 = 100.0;

impl Chair {
    fn new(s: &WheelchairSettings, person: &Physique) -> Self {
        let above_seat_mm = s
            .hip_above_seat_mm
            .or(person.legs.as_ref().map(|l| l.hip_above_seat_mm))
            .unwrap_or(HIP_ABOVE_SEAT_MM);
        let legs = person.legs.clone().map(|l| Legs {
            hip_above_seat_mm: above_seat_mm,
            ..l
        });
        let back_x_mm = person.column_mm.map_or(-130.0, |[lo, _]| lo.x) - 5.0;
        Chair {
            legs,
            hip_height_mm: s.seat_height_mm + above_seat_mm,
            back_x_mm,
        }
    }

    /// A box of the chair, `x` and `y` in the base frame, between heights
    /// `z` above the floor.
    fn part(&self, name: &str, x: [f64; 2], y: [f64; 2], z: [f64; 2]) -> Solid {
        let hip = self.hip_height_mm;
        let lo = Point3::new(x[0], y[0], z[0] - hip);
        let hi = Point3::new(x[1], y[1], z[1] - hip);
        Solid::new(
            format!("the wheelchair's {name}"),
            Shape::Cuboid(Cuboid::between(lo, hi)),
        )
    }

    /// Seat, backrest, wheels and (if it has them) armrests.
    fn parts(&self, s: &WheelchairSettings) -> Vec<Solid> {
        let (back, seat) = (self.back_x_mm, s.seat_height_mm);
        let half_seat = s.seat_width_mm / 2.0;
        let mut parts = vec![self.part(
            "seat",
            [back, back + s.seat_depth_mm],
            [-half_seat, half_seat],
            [seat - 60.0, seat],
        )];
        if s.backrest_mm > 0.0 {
            parts.push(self.part(
                "backrest",
                [back - 40.0, back],
                [-half_seat, half_seat],
                [seat, seat + s.backrest_mm],
            ));
        }
        let (axle, r, half) = (back + 60.0, s.wheel_mm / 2.0, s.width_mm / 2.0);
        for (side, y) in [
            ("left", [half - 35.0, half]),
            ("right", [-half, -half + 35.0]),
        ] {
            parts.push(self.part(
                &format!("{side} wheel"),
                [axle - r, axle + r],
                y,
                [0.0, 2.0 * r],
            ));
        }
        if s.armrests {
            let z = [s.armrest_height_mm - 40.0, s.armrest_height_mm];
            let x = [back, back + 330.0];
            parts.push(self.part("left armrest", x, [half_seat, half_seat + 50.0], z));
            parts.push(self.part("right armrest", x, [-half_seat - 50.0, -half_seat], z));
        }
        parts
    }

    /// One board under both feet of `legs` (the seated legs' solids).
    fn footrests(&self, s: &WheelchairSettings, legs: &[Solid]) -> Solid {
        let feet: Vec<[Point3<f64>; 2]> = legs
            .iter()
            .filter(|l| l.name.ends_with("foot"))
            .map(|l| l.shape.bounds())
            .collect();
        let x0 = feet
            .iter()
            .map(|[lo, _]| lo.x)
            .fold(f64::INFINITY, f64::min);
        let x1 = feet
            .iter()
            .map(|[_, hi]| hi.x)
            .fold(f64::NEG_INFINITY, f64::max);
        let sole = feet
            .iter()
            .map(|[lo, _]| lo.z)
            .fold(f64::INFINITY, f64::min);
        let half = s.footrest_width_mm / 2.0;
        // The soles' height above the floor.
        let top = sole + self.hip_height_mm;
        self.part("footrests", [x0, x1], [-half, half], [top - 30.0, top])
    }
}
