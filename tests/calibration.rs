//! The body reaches as far as measured people do (docs/calibration.md):
//! people built from ANSUR II's rows as `std::populations` builds them
//! reproduce their own measured reaches, and std::people's percentile
//! people their sex's percentiles. The reference points: ANSUR's
//! thumb-tip reach (the wall to the thumb's tip, the `thumb_tip`
//! effector) and seated overhead fingertip reach (the seat to the middle
//! fingertip, the `fingertip` effector).

use reach::ansur::survey;
use reach::calibration::{
    bodies, of_sex, percentile, reaches, standard_deviation, Reaches, PERCENTILE_PEOPLE,
};

/// Every 10th odd row (the even rows fitted the method's two constants).
fn sample() -> Vec<usize> {
    (1..survey().rows.len()).step_by(2).step_by(10).collect()
}

fn column(name: &str) -> usize {
    survey().columns.iter().position(|c| c == name).unwrap()
}

/// Model minus measured, for the people of `rows` of one sex.
fn errors(
    rows: &[usize],
    model: &[Reaches],
    female: bool,
    measure: usize,
    of: fn(&Reaches) -> f64,
) -> Vec<f64> {
    let survey = survey();
    rows.iter()
        .zip(model)
        .filter(|(&row, _)| survey.rows[row].female == female)
        .map(|(&row, r)| of(r) - survey.rows[row].lengths_mm[measure])
        .collect()
}

/// Per sex, on a few hundred odd rows: the median signed error within
/// 15 mm and the 90th-percentile absolute error at most 60 mm (thumb-tip
/// reach) and 70 mm (seated overhead fingertip reach). The full figures,
/// every odd row, are in docs/calibration.md.
#[test]
fn people_built_from_their_measurements_reach_as_far_as_they_were_measured_to() {
    let rows = sample();
    let built = bodies(&rows).unwrap_or_else(|d| panic!("{}", d.render(false)));
    let model: Vec<Reaches> = built.iter().map(|b| reaches(b).unwrap()).collect();
    let thumb = column("thumbtipreach");
    let overhead = column("overheadfingertipreachsitting");
    for female in [true, false] {
        for (what, measure, of, most) in [
            (
                "thumb-tip",
                thumb,
                (|r: &Reaches| r.thumb_tip_mm) as fn(&Reaches) -> f64,
                60.0,
            ),
            ("overhead", overhead, |r: &Reaches| r.overhead_mm, 70.0),
        ] {
            let e = errors(&rows, &model, female, measure, of);
            let abs: Vec<f64> = e.iter().map(|x| x.abs()).collect();
            let (median, p90) = (percentile(&e, 50.0), percentile(&abs, 90.0));
            assert!(e.len() > 80, "{} people", e.len());
            assert!(
                median.abs() <= 15.0 && p90 <= most,
                "{what} reach, {}: median error {median:.1} mm, 90th percentile {p90:.1} mm",
                if female { "women" } else { "men" }
            );
        }
    }
}

/// std::people's percentile people reach within one standard deviation
/// of their sex's percentile of the survey, on both reaches.
#[test]
fn the_percentile_people_reach_as_far_as_their_percentile_of_measured_people() {
    for (name, female, p) in PERCENTILE_PEOPLE {
        let body = reach::stdlib::body("people", name).unwrap();
        let model = reaches(&body).unwrap();
        for (measure, got) in [
            ("thumbtipreach", model.thumb_tip_mm),
            ("overheadfingertipreachsitting", model.overhead_mm),
        ] {
            let measured = of_sex(measure, female);
            assert!(measured.len() > 1000, "{measure}");
            let sd = standard_deviation(&measured);
            let want = percentile(&measured, p);
            assert!(
                (got - want).abs() <= sd,
                "{name}'s {measure}: {got:.0} mm, the measured percentile {want:.0} mm (SD {sd:.0})"
            );
        }
    }
}

/// The search realises the seated overhead reach: each seated person of
/// std::people, in a manual wheelchair in an empty room, reaches a point
/// straight above with the middle fingertip one standard deviation below
/// their sex's percentile of ANSUR's seated overhead fingertip reach (the
/// seat is 495 mm up), and not one standard deviation above it.
#[test]
fn seated_people_reach_overhead_with_the_fingertip_as_far_as_measured_people() {
    // Percentile and SD of the survey, women's 5th and men's 50th and 95th.
    let people = [
        ("woman_5th_seated", 1207.0, 62.0),
        ("man_50th_seated", 1426.0, 68.0),
        ("man_95th_seated", 1540.0, 68.0),
    ];
    let mut text =
        String::from("units mm deg\nuse std::people\nroom r {\n  size 3000 x 3000 x 3000\n");
    for (i, (_, measured, sd)) in people.iter().enumerate() {
        let (low, high) = (495.0 + measured - sd, 495.0 + measured + sd);
        text += &format!(
            "  target low_{i} at (1500, 1500, {low})\n  target high_{i} at (1500, 1500, {high})\n"
        );
    }
    text += "}\n";
    for (i, (mannequin, _, _)) in people.iter().enumerate() {
        text += &format!("person p{i} {{ mannequin {mannequin} base manual_wheelchair }}\n");
        text += &format!("reach low_{i}, high_{i} by p{i} {{ effector fingertip }}\n");
    }
    let (_, report) = crate::body::run(&text);
    for (i, (mannequin, _, _)) in people.iter().enumerate() {
        let person = format!("p{i}");
        let low = crate::body::reach_of(&report, &format!("low_{i}"), &person);
        assert!(low.ok, "{mannequin} does not reach {low:?}");
        assert_eq!(low.effector, "fingertip");
        let high = crate::body::reach_of(&report, &format!("high_{i}"), &person);
        assert!(!high.ok, "{mannequin} reaches {high:?}");
    }
}

/// `measured`'s `require`s say what no measured adult is: every row of
/// the survey, built as std::populations builds it, passes them.
#[test]
fn every_measured_adult_is_a_person_measured_may_build() {
    let rows: Vec<usize> = (0..survey().rows.len()).collect();
    for chunk in rows.chunks(1000) {
        if let Err(d) = bodies(chunk) {
            panic!("{}", d.render(false));
        }
    }
}

/// Standing, std::people's median man and 5th-percentile woman reach
/// forward (functional reach, Duncan et al. 1990) no farther than the
/// measured young adults' mean of their sex, and the tall man no farther
/// than that mean and one standard deviation; none short of the mean of
/// adults aged 70-87 (docs/calibration.md, "Standing forward reach").
#[test]
fn standing_people_lean_forward_no_farther_than_measured_people() {
    use reach::functional_reach::functional_reach;
    for (name, most_mm, least_mm) in [
        ("woman_5th", 372.0, 266.0),
        ("man_50th", 425.0, 334.0),
        ("man_95th", 425.0 + 49.0, 334.0),
    ] {
        let body = reach::stdlib::body("people", name).unwrap();
        let reach = functional_reach(name, &body).unwrap().reach_mm();
        assert!(
            reach <= most_mm && reach >= least_mm,
            "{name}: {reach} mm, measured people {least_mm}-{most_mm} mm"
        );
    }
}
