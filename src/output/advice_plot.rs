//! An advice's plot as SVG: the share of each group (a population, or a
//! person: 0 or 100 %) who reach the target at each position, one line
//! per group, the positions that serve every group shaded, the share
//! asked dashed and where the file puts the target dotted.

use std::fmt::Write;

use super::ticks::nice_step;
use crate::escape::markup;
use crate::report::AdviceReport;

const WIDTH: f64 = 760.0;
const HEIGHT: f64 = 430.0;
const LEFT: f64 = 64.0;
const RIGHT: f64 = 220.0;
const TOP: f64 = 48.0;
const BOTTOM: f64 = 56.0;

/// One colour per group, told apart in grey too.
const LINES: [&str; 6] = [
    "#1f6fb4", "#d9591c", "#2e9e4f", "#8e44ad", "#b8860b", "#444444",
];

/// The plot of `advices` (every advice about one target, in the order of
/// the report).
pub fn svg(advices: &[&AdviceReport]) -> String {
    let first = advices[0];
    let (lo, hi) = span_mm(advices);
    let half = first.step_mm / 2.0;
    let (x0, x1) = (lo - half, hi + half);
    let plot_w = WIDTH - LEFT - RIGHT;
    let plot_h = HEIGHT - TOP - BOTTOM;
    let x = |mm: f64| LEFT + (mm - x0) / (x1 - x0).max(1e-9) * plot_w;
    let y = |share: f64| TOP + (1.0 - share) * plot_h;
    let title = format!(
        "advise {}: who reaches it, by its {} (mm)",
        first.name, first.along
    );
    let mut s = page_start((WIDTH, HEIGHT), LEFT, &title);
    // The positions that serve every group: shaded.
    for (from, to) in AdviceReport::served_together(advices) {
        let _ = writeln!(
            s,
            r##"<rect x="{:.1}" y="{TOP}" width="{:.1}" height="{plot_h}" fill="#cfe8d4"><title>{} serves every group</title></rect>"##,
            x(from - half),
            x(to + half) - x(from - half),
            markup(&span_words(from, to))
        );
    }
    axes(&mut s, (x0, x1), &x, &y);
    // The share asked of the populations, dashed.
    let mut asked: Vec<f64> = (advices.iter())
        .filter(|a| a.population)
        .map(|a| a.serves)
        .collect();
    asked.sort_by(f64::total_cmp);
    asked.dedup();
    for share in asked {
        let _ = writeln!(
            s,
            r##"<line x1="{LEFT}" x2="{:.1}" y1="{:.1}" y2="{:.1}" stroke="#555" stroke-dasharray="6 4"/><text x="{:.1}" y="{:.1}" fill="#555" text-anchor="end">asked {:.0} %</text>"##,
            LEFT + plot_w,
            y(share),
            y(share),
            LEFT + plot_w - 4.0,
            y(share) - 4.0,
            share * 100.0
        );
    }
    // Where the file puts it, dotted.
    let declared = first.declared_mm;
    if (x0..=x1).contains(&declared) {
        let _ = writeln!(
            s,
            r##"<line x1="{0:.1}" x2="{0:.1}" y1="{TOP}" y2="{1:.1}" stroke="#777" stroke-dasharray="2 3"/><text x="{0:.1}" y="{2:.1}" fill="#777" text-anchor="middle">as declared</text>"##,
            x(declared),
            TOP + plot_h,
            TOP - 6.0
        );
    }
    // Each standard's rule for the element: where it holds, a bar along
    // the foot of the plot.
    for (k, rule) in first.standards.iter().enumerate() {
        let bar_y = TOP + plot_h - 8.0 - k as f64 * 16.0;
        for [from, to] in &rule.ranges {
            let _ = writeln!(
                s,
                r##"<line x1="{:.1}" x2="{:.1}" y1="{bar_y:.1}" y2="{bar_y:.1}" stroke="#333" stroke-width="5"><title>{}</title></line>"##,
                x(from - half),
                x(to + half),
                markup(&format!(
                    "{} {}: {}",
                    rule.standard,
                    rule.sections.join(", "),
                    rule.rule
                ))
            );
        }
        let holds = if rule.ranges.is_empty() {
            "holds nowhere here"
        } else {
            "holds"
        };
        let label = format!("{} {} {holds}", rule.standard, rule.sections.join(", "));
        let label_x = rule
            .ranges
            .first()
            .map_or(LEFT + 4.0, |r| x(r[0] - half) + 4.0);
        let _ = writeln!(
            s,
            r##"<text x="{label_x:.1}" y="{:.1}" fill="#333">{}</text>"##,
            bar_y - 5.0,
            markup(&label)
        );
    }
    // Lines drawn first are wider, so that one under another that runs
    // along it still shows at its edges.
    let n = advices.len();
    for (k, advice) in advices.iter().enumerate() {
        let width = 2.0 + 2.0 * (n - 1 - k) as f64;
        line(&mut s, advice, LINES[k % LINES.len()], width, &x, &y);
        legend(&mut s, k, advice, LINES[k % LINES.len()]);
    }
    let key_y = TOP + 6.0 + n as f64 * 40.0;
    let key_x = WIDTH - RIGHT + 16.0;
    let _ = writeln!(
        s,
        r##"<rect x="{key_x}" y="{:.1}" width="22" height="12" fill="#cfe8d4"/><text x="{:.1}" y="{:.1}">serves every group</text>"##,
        key_y - 6.0,
        key_x + 28.0,
        key_y + 4.0
    );
    s.push_str("</svg>\n");
    s
}

/// An advice picture's opening: the `svg` element `width` by `height`,
/// a white ground and `title` at `left`.
pub(super) fn page_start((width, height): (f64, f64), left: f64, title: &str) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" viewBox="0 0 {width} {height}" font-family="sans-serif" font-size="12">"#
    );
    let _ = writeln!(
        s,
        r#"<rect width="{width}" height="{height}" fill="white"/>"#
    );
    let _ = writeln!(
        s,
        r#"<text x="{left}" y="22" font-size="15" font-weight="bold">{}</text>"#,
        markup(title)
    );
    s
}

/// The lowest and highest position of any of `advices`.
fn span_mm(advices: &[&AdviceReport]) -> (f64, f64) {
    let all = advices
        .iter()
        .flat_map(|a| a.points.iter().map(|p| p.at_mm));
    all.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    })
}

fn span_words(from: f64, to: f64) -> String {
    if from == to {
        format!("{from} mm")
    } else {
        format!("{from}-{to} mm")
    }
}

/// The frame, the shares' grid and the positions' round ticks.
fn axes(s: &mut String, (x0, x1): (f64, f64), x: &impl Fn(f64) -> f64, y: &impl Fn(f64) -> f64) {
    let (left, right) = (x(x0), x(x1));
    for k in 0..=4 {
        let share = f64::from(k) / 4.0;
        let _ = writeln!(
            s,
            r##"<line x1="{left:.1}" x2="{right:.1}" y1="{0:.1}" y2="{0:.1}" stroke="#ddd"/><text x="{1:.1}" y="{2:.1}" text-anchor="end">{3} %</text>"##,
            y(share),
            left - 6.0,
            y(share) + 4.0,
            k * 25
        );
    }
    // Ticks at least 60 px apart.
    let per_px = (x1 - x0) / (right - left).max(1e-9);
    let step = nice_step(60.0 * per_px);
    let mut tick = (x0 / step).ceil() * step;
    while tick <= x1 + 1e-9 {
        let _ = writeln!(
            s,
            r##"<line x1="{0:.1}" x2="{0:.1}" y1="{1:.1}" y2="{2:.1}" stroke="black"/><text x="{0:.1}" y="{3:.1}" text-anchor="middle">{4}</text>"##,
            x(tick),
            y(0.0),
            y(0.0) + 5.0,
            y(0.0) + 19.0,
            tick
        );
        tick += step;
    }
    let _ = writeln!(
        s,
        r#"<rect x="{left:.1}" y="{:.1}" width="{:.1}" height="{:.1}" fill="none" stroke="black"/>"#,
        y(1.0),
        right - left,
        y(0.0) - y(1.0)
    );
    let _ = writeln!(
        s,
        r#"<text x="{:.1}" y="{:.1}" text-anchor="middle">position of the target (mm)</text>"#,
        (left + right) / 2.0,
        y(0.0) + 40.0
    );
}

/// One group's shares, point to point.
fn line(
    s: &mut String,
    advice: &AdviceReport,
    colour: &str,
    width: f64,
    x: &impl Fn(f64) -> f64,
    y: &impl Fn(f64) -> f64,
) {
    let points: Vec<String> = (advice.points.iter())
        .map(|p| format!("{:.1},{:.1}", x(p.at_mm), y(p.share)))
        .collect();
    let _ = writeln!(
        s,
        r#"<polyline points="{}" fill="none" stroke="{colour}" stroke-width="{width:.1}" stroke-linejoin="round"><title>{}</title></polyline>"#,
        points.join(" "),
        markup(&advice.who)
    );
}

/// The group's entry in the legend: its name, and its served range.
fn legend(s: &mut String, k: usize, advice: &AdviceReport, colour: &str) {
    let top = TOP + 6.0 + k as f64 * 40.0;
    let left = WIDTH - RIGHT + 16.0;
    let ranges: Vec<String> = (advice.ranges.iter())
        .map(|r| span_words(r.from_mm, r.to_mm))
        .collect();
    let served = if ranges.is_empty() {
        "nowhere".to_string()
    } else {
        ranges.join(", ")
    };
    let who = if advice.population {
        format!("{} ({})", advice.who, advice.people)
    } else {
        advice.who.clone()
    };
    let _ = writeln!(
        s,
        r##"<line x1="{left}" x2="{:.1}" y1="{top}" y2="{top}" stroke="{colour}" stroke-width="3"/><text x="{:.1}" y="{:.1}">{}</text><text x="{:.1}" y="{:.1}" fill="#555">{}</text>"##,
        left + 22.0,
        left + 28.0,
        top + 4.0,
        markup(&who),
        left + 28.0,
        top + 19.0,
        markup(&format!("serves {served}"))
    );
}
