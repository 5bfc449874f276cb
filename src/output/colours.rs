//! The colours of map cells, one set for the SVG maps, the 3D page and
//! the glTF scene: reached or seen, missed, bands of how far short a
//! point fell, and bands of the share of a population who reach it.

/// Reached, seen (and a line of sight), missed (not seen, or a target
/// not reached).
pub const REACHED: &str = "#2e9e4f";
pub const SEEN: &str = "#2b6cd6";
pub const MISSED: &str = "#d64545";
/// Short by up to 75, 150, 225 and 225 mm or more.
pub const SHORT: [(&str, &str); 4] = [
    ("#e8d44d", "short by up to 75 mm"),
    ("#e6a84a", "75-150 mm"),
    ("#df7d48", "150-225 mm"),
    (MISSED, "225 mm or more"),
];
/// A point not reached whose closest posture came within the tolerance
/// only through something (an obstacle, the person's own body): not
/// short, blocked.
pub const THROUGH: (&str, &str) = ("#c463c9", "there only through something");
/// A population map's cell colours: the share of its people who reach
/// (or see) a point, from everyone down to no one. A share counts in the
/// first band whose least it reaches.
pub const SHARES: [(f64, &str, &str); 6] = [
    (1.0, "#1a7a36", "everyone"),
    (0.95, "#5cb85c", "95 % or more"),
    (0.8, "#e8d44d", "80-95 %"),
    (0.5, "#e6a84a", "50-80 %"),
    (1e-9, "#df7d48", "under 50 %"),
    (f64::NEG_INFINITY, MISSED, "no one"),
];

/// The colour of a point a share `share` of a population reaches.
pub fn share_colour(share: f64) -> &'static str {
    SHARES
        .iter()
        .find(|(least, ..)| share >= *least)
        .map_or(MISSED, |(_, colour, _)| colour)
}

/// What the 3D view's cells carry for a point there only through
/// something, in place of how far short it fell.
pub const THROUGH_MARK: f64 = -1.0;

/// A point's colour as the 3D view gives it: `of` is `reach`, `gaze` or
/// `share`, `value` how far short (0 where reached or seen,
/// [`THROUGH_MARK`] where there only through something) or the share of
/// a population.
pub fn view_cell_colour(of: &str, value: f64) -> &'static str {
    match of {
        "share" => share_colour(value),
        _ if value < 0.0 => THROUGH.0,
        _ => cell_colour(of, value <= 0.0, value),
    }
}

/// A map point's colour: reached or seen, not seen, or its band of
/// shortfall (`short_mm`, the distance left).
pub fn cell_colour(of: &str, reachable: bool, short_mm: f64) -> &'static str {
    match (reachable, of) {
        (true, "gaze") => SEEN,
        (true, _) => REACHED,
        (false, "gaze") => MISSED,
        (false, _) => SHORT[(short_mm / 75.0).floor().clamp(0.0, 3.0) as usize].0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_share_takes_the_band_whose_least_it_reaches() {
        assert_eq!(share_colour(1.0), SHARES[0].1);
        assert_eq!(share_colour(0.999), SHARES[1].1);
        assert_eq!(share_colour(0.95), SHARES[1].1);
        assert_eq!(share_colour(0.5), SHARES[3].1);
        assert_eq!(share_colour(0.01), SHARES[4].1);
        assert_eq!(share_colour(0.0), MISSED);
    }
}
