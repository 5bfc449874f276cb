//! Visual acuity after the visibility paper: the distances at which an
//! object of a given size is legible (eq. 1-2, the Snellen principle), and
//! how acuity falls off away from the fovea (eq. 3).

/// One minute of arc in radians.
pub const ARCMIN_RAD: f64 = std::f64::consts::PI / 10_800.0;

/// The farthest an object of size `size_mm` is legible (eq. 1): a Snellen
/// letter is five times the minimum angle of resolution, so
/// `D_max = S / (5 tan MAR_far)`.
pub fn d_max_mm(size_mm: f64, mar_far_rad: f64) -> f64 {
    size_mm / (5.0 * mar_far_rad.tan())
}

/// The nearest distance of eq. 2, `D_min = S / (5 tan MAR_near)`.
pub fn d_min_mm(size_mm: f64, mar_near_rad: f64) -> f64 {
    size_mm / (5.0 * mar_near_rad.tan())
}

/// Acuity relative to the fovea at `theta_rad` off the line of sight
/// (eq. 3): `e^(-7 |theta|)`.
pub fn acuity(theta_rad: f64) -> f64 {
    (-7.0 * theta_rad.abs()).exp()
}

/// The largest angle off the line of sight at which acuity is still at
/// least `threshold` (the inverse of eq. 3).
pub fn max_angle_rad(threshold: f64) -> f64 {
    -threshold.ln() / 7.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_letter_of_8_7_mm_is_legible_to_6_m_with_normal_acuity() {
        // The 20/20 Snellen letter at 6 m subtends 5 arcmin: 8.73 mm.
        let s = 6000.0 * (5.0 * ARCMIN_RAD).tan();
        assert!((d_max_mm(s, ARCMIN_RAD) - 6000.0).abs() < 1.0, "{s}");
    }

    #[test]
    fn a_larger_near_mar_brings_d_min_closer() {
        assert!((d_min_mm(20.0, 2.0 * ARCMIN_RAD) - d_max_mm(20.0, ARCMIN_RAD) / 2.0).abs() < 0.01);
    }

    #[test]
    fn acuity_falls_off_as_eq_3() {
        assert_eq!(acuity(0.0), 1.0);
        assert!((acuity(-0.1) - (-0.7_f64).exp()).abs() < 1e-15);
        assert!((acuity(max_angle_rad(0.5)) - 0.5).abs() < 1e-12);
    }
}
