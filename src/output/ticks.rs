//! Round ticks for the axes of the SVG pictures (maps, advice plots).

/// A round step (1, 2 or 5 times a power of ten) for ticks at least
/// `min_mm` apart.
pub fn nice_step(min_mm: f64) -> f64 {
    let power = 10f64.powf(min_mm.max(1e-9).log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|k| k * power)
        .find(|&step| step >= min_mm)
        .unwrap_or(10.0 * power)
}
