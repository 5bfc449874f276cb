//! The `trolley` base: a person standing with a rollator or a kitchen
//! trolley in front of them. The hip point is at the person's standing hip
//! height (the mannequin's legs, or `hip_height`); the frame's two sides and
//! its seat, and the person's legs, are solids the arm must stay out of and
//! what the floor must find room for. It turns with the heading.
//!
//! Defaults: a frame 600 mm wide (walking frames 550-600 mm: Scottish
//! Government, Housing for Varying Needs, 2.3) and 610 mm long, handles
//! 830-935 mm high on one product sheet, set at the wrist crease (0.485 of
//! stature, against the hip's 0.530: Drillis & Contini), a seat 560 mm high
//! (Stiftung Warentest's rollators, 540-600 mm). Assumed: the frame starts
//! 150 mm ahead of the hip point, beside the feet; its sides 30 mm thick.

use nalgebra::Point3;

use super::placement::Mobile;
use super::PlacingSettings;
use crate::geometry::{Cuboid, Shape, Solid};
use crate::kinematics::Stance;
use crate::plugin::{Base, BaseError, BasePlugin, Options, ParamSpec, Params, Plugin, Settings};
use crate::scene::Physique;

/// The plugin `trolley`.
pub struct Trolley;

/// Its settings.
#[derive(Clone, Debug, PartialEq)]
pub struct TrolleySettings {
    pub hip_height_mm: Option<f64>,
    pub width_mm: f64,
    pub length_mm: f64,
    pub ahead_mm: f64,
    pub handle_height_mm: Option<f64>,
    pub seat_height_mm: f64,
    pub placing: PlacingSettings,
}

impl Settings for TrolleySettings {
    fn visit(p: &mut Params<'_>) -> Self {
        TrolleySettings {
            hip_height_mm: p
                .optional_length(
                    "hip_height",
                    "height of the hip point (default: the mannequin's legs)",
                )
                .range(200.0, 1500.0)
                .get(),
            width_mm: p
                .length("width", 600.0, "the frame's width")
                .range(200.0, 2000.0)
                .get(),
            length_mm: p
                .length("length", 610.0, "the frame's length")
                .range(100.0, 2000.0)
                .get(),
            ahead_mm: p
                .length(
                    "ahead",
                    150.0,
                    "from the hip point forward to the frame's back",
                )
                .range(-500.0, 1500.0)
                .get(),
            handle_height_mm: p
                .optional_length(
                    "handle_height",
                    "the handles' height (default: the wrist's, 0.915 of the hip's)",
                )
                .range(200.0, 2000.0)
                .get(),
            seat_height_mm: p
                .length("seat_height", 560.0, "the seat's height (0: none)")
                .range(0.0, 2000.0)
                .get(),
            placing: PlacingSettings::visit(
                p,
                "one corner of the floor zone the person must stay in",
            ),
        }
    }
}

impl Plugin for Trolley {
    fn name(&self) -> &'static str {
        "trolley"
    }

    fn doc(&self) -> &'static str {
        "standing with a rollator or trolley in front: its frame and the legs, turning with the person"
    }

    fn params(&self) -> Vec<ParamSpec> {
        TrolleySettings::params()
    }
}

/// The wrist crease's height over the hip's, standing (0.485 / 0.530 of
/// stature: Drillis & Contini).
const WRIST_OVER_HIP: f64 = 0.485 / 0.530;

impl BasePlugin for Trolley {
    fn build(&self, options: &Options, person: &Physique) -> Result<Box<dyn Base>, BaseError> {
        let s = TrolleySettings::from_options(options)?;
        if let Some(declared @ Stance::Seated) = person.posture {
            return Err(BaseError::posture("trolley", declared, Stance::Standing));
        }
        let hip_height_mm = s
            .hip_height_mm
            .or(person.legs.as_ref().map(|l| l.hip_height_mm))
            .ok_or_else(|| {
                BaseError::Unfit(
                    "the mannequin has no `legs` to stand on: give the trolley a `hip_height`"
                        .into(),
                )
            })?;
        let mut solids = frame(&s, hip_height_mm);
        if let Some(legs) = &person.legs {
            solids.extend(legs.standing());
        }
        let pelvis = person.legs.as_ref().map_or(0.0, |l| l.pelvis_mm);
        let mut base =
            Mobile::carrying(solids, person, pelvis, hip_height_mm, s.placing.placing()?);
        base.own = base.own.standing_placed(person);
        Ok(Box::new(base))
    }
}

/// The frame's sides (to the handles) and seat, in the base frame.
fn frame(s: &TrolleySettings, hip_height_mm: f64) -> Vec<Solid> {
    let handles = s.handle_height_mm.unwrap_or(WRIST_OVER_HIP * hip_height_mm);
    let (x0, x1, half) = (s.ahead_mm, s.ahead_mm + s.length_mm, s.width_mm / 2.0);
    let part = |name: &str, x: [f64; 2], y: [f64; 2], z: [f64; 2]| {
        let lo = Point3::new(x[0], y[0], z[0] - hip_height_mm);
        let hi = Point3::new(x[1], y[1], z[1] - hip_height_mm);
        Solid::new(
            format!("the trolley's {name}"),
            Shape::Cuboid(Cuboid::between(lo, hi)),
        )
    };
    let mut parts = vec![
        part("left side", [x0, x1], [half - 30.0, half], [0.0, handles]),
        part(
            "right side",
            [x0, x1],
            [-half, -half + 30.0],
            [0.0, handles],
        ),
    ];
    if s.seat_height_mm > 0.0 {
        let x = [x0 + 0.25 * s.length_mm, x0 + 0.85 * s.length_mm];
        let z = [s.seat_height_mm - 40.0, s.seat_height_mm];
        parts.push(part("seat", x, [-half + 30.0, half - 30.0], z));
    }
    parts
}
