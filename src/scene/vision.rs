//! What a person's eyes make out, as settings a gaze task and a person's
//! `vision` may each give or leave out: the minimum angles of resolution,
//! the near point and the acuity threshold. A gaze takes each from the
//! task, else from the person, else the default of [`Vision::DEFAULT`].

use crate::options::{Params, Settings};
use crate::vision::ARCMIN_RAD;

/// Vision settings, each `None` where left out.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Vision {
    /// Minimum angle of resolution, far vision (eq. 1).
    pub mar_far_rad: Option<f64>,
    /// Minimum angle of resolution, near vision (eq. 2).
    pub mar_near_rad: Option<f64>,
    /// The nearest distance the eyes focus at, when `mar_near` is not given.
    pub near_point_mm: Option<f64>,
    /// The least acuity e^(-7 |angle|) at which a target counts as seen.
    pub acuity: Option<f64>,
}

impl Vision {
    /// The defaults of what a task and a person leave out (no near MAR:
    /// the nearest distance is the near point).
    pub const DEFAULT: Vision = Vision {
        mar_far_rad: Some(ARCMIN_RAD),
        mar_near_rad: None,
        near_point_mm: Some(250.0),
        acuity: Some(0.5),
    };

    /// Each setting from `self`, else from `fallback`.
    pub fn or(&self, fallback: &Vision) -> Vision {
        Vision {
            mar_far_rad: self.mar_far_rad.or(fallback.mar_far_rad),
            mar_near_rad: self.mar_near_rad.or(fallback.mar_near_rad),
            near_point_mm: self.near_point_mm.or(fallback.near_point_mm),
            acuity: self.acuity.or(fallback.acuity),
        }
    }
}

impl Settings for Vision {
    fn visit(p: &mut Params<'_>) -> Self {
        Vision {
            mar_far_rad: p
                .optional_angle(
                    "mar_far",
                    "minimum angle of resolution, far vision (eq. 1); default 1arcmin",
                )
                .range(0.01 * ARCMIN_RAD, 600.0 * ARCMIN_RAD)
                .get(),
            mar_near_rad: p
                .optional_angle(
                    "mar_near",
                    "minimum angle of resolution, near vision (eq. 2); if left out the nearest distance is `near_point`",
                )
                .range(0.01 * ARCMIN_RAD, 600.0 * ARCMIN_RAD)
                .get(),
            near_point_mm: p
                .optional_length(
                    "near_point",
                    "the nearest distance the eyes focus at when `mar_near` is not given; default 250mm",
                )
                .range(0.0, 10_000.0)
                .get(),
            acuity: p
                .optional_number(
                    "acuity",
                    "the least acuity e^(-7 |angle|) at which the target counts as seen (eq. 3); default 0.5",
                )
                .range(0.001, 1.0)
                .get(),
        }
    }
}
