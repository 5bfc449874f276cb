//! One Denavit-Hartenberg link: `T = Rz(theta) Tz(d) Tx(a) Rx(alpha)`, the
//! matrix of eq. 3 of the accessibility paper.

use nalgebra::{IsometryMatrix3, Matrix3, Rotation3, Translation3};

/// The constant part of a link. The joint variable is added to `theta_rad`
/// (revolute) or `d_mm` (prismatic). The twist `alpha` is kept with its
/// sine and cosine, worked out once (every pose of the link needs them).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dh {
    pub theta_rad: f64,
    pub d_mm: f64,
    alpha_rad: f64,
    pub a_mm: f64,
    /// `alpha_rad.sin_cos()`.
    alpha_sin_cos: (f64, f64),
}

impl Default for Dh {
    fn default() -> Self {
        Dh::new(0.0, 0.0, 0.0, 0.0)
    }
}

impl Dh {
    pub fn new(theta_rad: f64, d_mm: f64, alpha_rad: f64, a_mm: f64) -> Self {
        Dh {
            theta_rad,
            d_mm,
            alpha_rad,
            a_mm,
            alpha_sin_cos: alpha_rad.sin_cos(),
        }
    }

    /// The twist about the new x axis.
    pub fn alpha_rad(&self) -> f64 {
        self.alpha_rad
    }

    /// The sine and cosine of the twist.
    pub fn alpha_sin_cos(&self) -> (f64, f64) {
        self.alpha_sin_cos
    }

    /// The pose of frame i in frame i-1 for the given theta and d.
    pub fn transform(&self, theta_rad: f64, d_mm: f64) -> IsometryMatrix3<f64> {
        let (st, ct) = theta_rad.sin_cos();
        let (sa, ca) = self.alpha_sin_cos;
        let rotation = Matrix3::new(
            ct,
            -ca * st,
            sa * st, //
            st,
            ca * ct,
            -sa * ct, //
            0.0,
            sa,
            ca,
        );
        IsometryMatrix3::from_parts(
            Translation3::new(self.a_mm * ct, self.a_mm * st, d_mm),
            Rotation3::from_matrix_unchecked(rotation),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Point3, Vector3};
    use std::f64::consts::FRAC_PI_2;

    fn dh(theta_rad: f64, d_mm: f64, alpha_rad: f64, a_mm: f64) -> Dh {
        Dh::new(theta_rad, d_mm, alpha_rad, a_mm)
    }

    #[test]
    fn identity_parameters_give_the_identity() {
        let t = dh(0.0, 0.0, 0.0, 0.0).transform(0.0, 0.0);
        assert!((t.to_homogeneous() - nalgebra::Matrix4::identity()).norm() < 1e-15);
    }

    #[test]
    fn matches_the_product_of_elementary_motions() {
        // Rz(theta) Tz(d) Tx(a) Rx(alpha), composed by nalgebra itself.
        let (theta, d, alpha, a) = (0.3, 12.0, -1.1, 7.0);
        let expected = IsometryMatrix3::from_parts(
            Translation3::identity(),
            Rotation3::from_axis_angle(&Vector3::z_axis(), theta),
        ) * Translation3::new(0.0, 0.0, d)
            * Translation3::new(a, 0.0, 0.0)
            * Rotation3::from_axis_angle(&Vector3::x_axis(), alpha);
        let got = dh(theta, 0.0, alpha, a).transform(theta, d);
        assert!((got.to_homogeneous() - expected.to_homogeneous()).norm() < 1e-12);
    }

    #[test]
    fn worked_example_quarter_turns() {
        // theta = 90 deg, alpha = 90 deg, a = 10, d = 5: the new x axis is
        // the old y axis, the new z axis is the old x axis, and the origin
        // moves to (0, 10, 5).
        let t = dh(FRAC_PI_2, 0.0, FRAC_PI_2, 10.0).transform(FRAC_PI_2, 5.0);
        let origin = t * Point3::origin();
        assert!((origin - Point3::new(0.0, 10.0, 5.0)).norm() < 1e-12);
        let x = t * Vector3::x();
        let z = t * Vector3::z();
        assert!((x - Vector3::y()).norm() < 1e-12);
        assert!((z - Vector3::x()).norm() < 1e-12);
    }
}
