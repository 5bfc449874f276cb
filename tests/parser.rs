//! Parser tests, table-driven: text in, syntax tree (or message) out.

use reach::span::FileId;
use reach::syntax::ast::*;
use reach::syntax::parse_file;
use reach::units::Unit;

fn parse(text: &str) -> File {
    match parse_file(FileId(0), text) {
        Ok(f) => f,
        Err(d) => panic!("{text:?} does not parse: {:?}", d.errors[0].kind()),
    }
}

fn parse_error(text: &str) -> String {
    match parse_file(FileId(0), text) {
        Ok(f) => panic!("{text:?} parses: {f:?}"),
        Err(d) => d.errors[0].kind().to_string(),
    }
}

/// The value of `let x = ...` as an S-expression, for compact tables.
fn sexpr(e: &Expr) -> String {
    match &e.kind {
        ExprKind::Number { value, unit } => match unit {
            Some(u) => format!("{value}{}", u.symbol()),
            None => format!("{value}"),
        },
        ExprKind::Name(n) => n.clone(),
        ExprKind::Neg(inner) => format!("(neg {})", sexpr(inner)),
        ExprKind::Binary(op, l, r) => {
            let op = match op {
                BinOp::Add => "+",
                BinOp::Sub => "-",
                BinOp::Mul => "*",
                BinOp::Div => "/",
            };
            format!("({op} {} {})", sexpr(l), sexpr(r))
        }
        ExprKind::Call(f, args) => {
            let f = match f {
                Function::Min => "min",
                Function::Max => "max",
            };
            let args: Vec<String> = args.iter().map(sexpr).collect();
            format!("({f} {})", args.join(" "))
        }
    }
}

fn let_value(text: &str) -> String {
    let file = parse(&format!("let x = {text}"));
    match &file.items[..] {
        [Item::Let(d)] => sexpr(&d.value),
        other => panic!("{other:?}"),
    }
}

#[test]
fn expressions() {
    let cases = [
        ("900", "900"),
        ("900mm", "900mm"),
        ("2.5cm", "2.5cm"),
        ("1.5e3mm", "1500mm"),
        ("90deg", "90deg"),
        ("3arcmin", "3arcmin"),
        ("1 + 2 * 3", "(+ 1 (* 2 3))"),
        ("(1 + 2) * 3", "(* (+ 1 2) 3)"),
        ("a - b - c", "(- (- a b) c)"),
        ("a / b * c", "(* (/ a b) c)"),
        ("-a * 2", "(* (neg a) 2)"),
        ("-(a + 1m)", "(neg (+ a 1m))"),
        ("counter_h + 60", "(+ counter_h 60)"),
        ("0.818 - 0.530", "(- 0.818 0.53)"),
        ("30%", "30%"),
        ("30 %", "30%"),
        ("min(a, 2mm)", "(min a 2mm)"),
        ("max(a, b, c) / 2", "(/ (max a b c) 2)"),
        ("-min(a, b)", "(neg (min a b))"),
        ("mini + min", "(+ mini min)"),
    ];
    for (text, expected) in cases {
        assert_eq!(let_value(text), expected, "parsing {text:?}");
    }
}

#[test]
fn spans_are_ignored_by_equality() {
    let a = parse("let a = 1 + 2\nroom k { size 1 x 2 x 3 }");
    let b = parse("let   a=1+2   // comment\n/* block\ncomment */ room k{size 1 x 2 x 3}");
    assert_eq!(a, b);
}

#[test]
fn both_room_size_forms_mean_the_same() {
    let a = parse("room k { size 3600 x 2800 x 2500 }");
    let b = parse("room k { size (3600, 2800, 2500) }");
    assert_eq!(a, b);
}

#[test]
fn declarations() {
    let file = parse(
        r#"
        units cm rad
        use std::arm
        use "parts/cabinets.reach"
        room kitchen {
          size 360 x 280 x 250
          box counter at (0, 0, 0) size (60, 280, 90) rotate 10deg
          target mug at (30, 120, 96)
        }
        mannequin arm {
          joint shoulder prismatic dh(theta 0, d 10) limits(0, 5)
          joint elbow dh(a 30) limits(0deg, 150deg) neutral 30deg weight 2
          effector hand at (20, 0, 0)
        }
        person ann {
          mannequin arm { limits elbow (0deg, 90deg) neutral elbow 10deg weight elbow 3 }
          base fixed { at (90, 120, 93), heading 180deg }
        }
        reach mug, kettle by ann, ben { solver incremental { rate 0.2 sign_memory false } tolerance 5mm }
        mannequin short_arm = arm(len 20, width 3)
        profile stiff { limits elbow (0deg, 10deg) }
        base big_chair = wheelchair { seat_height 50 }
        vision blurry { mar_far 2arcmin }
        limits { solver_work 2e9 }
        "#,
    );
    let kinds: Vec<&str> = file
        .items
        .iter()
        .map(|i| match i {
            Item::Units(_) => "units",
            Item::Use(_) => "use",
            Item::Let(_) => "let",
            Item::Room(_) => "room",
            Item::Mannequin(_) => "mannequin",
            Item::Profile(_) => "profile",
            Item::BasePreset(_) => "base preset",
            Item::VisionPreset(_) => "vision",
            Item::Person(_) => "person",
            Item::Population(_) => "population",
            Item::Standard(_) => "standard",
            Item::Limits(_) => "limits",
            Item::Expect(_) => "expect",
            Item::Task(_) => "task",
        })
        .collect();
    assert_eq!(
        kinds,
        [
            "units",
            "use",
            "use",
            "room",
            "mannequin",
            "person",
            "task",
            "mannequin",
            "profile",
            "base preset",
            "vision",
            "limits"
        ]
    );
    let Item::Mannequin(alias) = &file.items[7] else {
        unreachable!()
    };
    let target = alias.alias.as_ref().unwrap();
    assert_eq!(target.name.value, "arm");
    let args: Vec<&str> = target.args.iter().map(|(n, _)| n.value.as_str()).collect();
    assert_eq!(args, ["len", "width"]);

    let Item::Units(units) = &file.items[0] else {
        unreachable!()
    };
    assert_eq!(
        units.iter().map(|u| u.value).collect::<Vec<_>>(),
        [Unit::Cm, Unit::Rad]
    );
    let Item::Use(u) = &file.items[1] else {
        unreachable!()
    };
    assert_eq!(u.value, UseTarget::Std("arm".into()));
    let Item::Use(u) = &file.items[2] else {
        unreachable!()
    };
    assert_eq!(u.value, UseTarget::Path("parts/cabinets.reach".into()));

    let Item::Room(room) = &file.items[3] else {
        unreachable!()
    };
    assert_eq!(room.items.len(), 3);
    let RoomItem::Box(b) = &room.items[1] else {
        unreachable!()
    };
    assert_eq!(b.name.value, "counter");
    assert!(b.rotate.is_some());

    let Item::Mannequin(m) = &file.items[4] else {
        unreachable!()
    };
    assert_eq!(m.joints[0].kind, JointKind::Prismatic);
    assert_eq!(m.joints[1].kind, JointKind::Revolute);
    assert_eq!(m.joints[1].dh.len(), 1);
    assert_eq!(m.joints[1].neutral.len(), 1);
    assert_eq!(m.effectors[0].name.value, "hand");

    let Item::Person(p) = &file.items[5] else {
        unreachable!()
    };
    assert_eq!(p.mannequins[0].overrides.len(), 3);
    assert_eq!(p.bases[0].name.value, "fixed");
    assert_eq!(p.bases[0].options.len(), 2);

    let Item::Task(t) = &file.items[6] else {
        unreachable!()
    };
    assert_eq!(t.kind.value, "reach");
    assert_eq!(
        t.subjects
            .iter()
            .map(|s| s.value.join("."))
            .collect::<Vec<_>>(),
        ["mug", "kettle"]
    );
    assert_eq!(
        t.persons
            .iter()
            .map(|p| p.value.as_str())
            .collect::<Vec<_>>(),
        ["ann", "ben"]
    );
    let OptionValue::Plugin(solver) = &t.options[0].value else {
        panic!("{:?}", t.options[0])
    };
    assert_eq!(solver.name.value, "incremental");
    assert!(matches!(solver.options[1].value, OptionValue::Bool(false)));
}

#[test]
fn dotted_subjects_for_surfaces() {
    let file = parse("map counter.top by ann");
    let Item::Task(t) = &file.items[0] else {
        unreachable!()
    };
    assert_eq!(t.subjects[0].value, ["counter", "top"]);
}

#[test]
fn syntax_errors_say_what_was_expected() {
    let cases = [
        (
            "room kitchen {",
            "expected `size`, `box`, `target`, `mesh`, `surface`, `door` or `}`, found end of file",
        ),
        ("let = 5", "expected a name, found `=`"),
        ("let x 5", "expected `=`, found `5`"),
        ("let x = ", "expected an expression, found end of file"),
        ("let x = (1, 2)", "found `,`"),
        (
            "room k { box b at (0, 0) size (1, 1, 1) }",
            "expected `,` or an operator, found `)`",
        ),
        (
            "reach mug",
            "expected `,`, `and` or `by`, found end of file",
        ),
        ("person p { mannequin }", "expected a name, found `}`"),
        ("let room = 1", "expected a name, found `room`"),
    ];
    for (text, expected) in cases {
        let message = parse_error(text);
        assert!(
            message.contains(expected),
            "{text:?}: {message:?} lacks {expected:?}"
        );
        assert!(
            !message.contains("_decl") && !message.contains("EOI"),
            "rule name leaked: {message}"
        );
    }
}

#[test]
fn literal_errors_are_all_reported() {
    let d = parse_file(FileId(0), "let a = 5mx\nlet b = 1e400\nlet c = 3cm").unwrap_err();
    let messages: Vec<String> = d.errors.iter().map(|e| e.kind().to_string()).collect();
    assert_eq!(
        messages,
        [
            "unknown unit `mx`",
            "`1e400` is too large or not a finite number"
        ]
    );
}

#[test]
fn a_declaration_span_ends_at_its_last_token_not_at_comments_after_it() {
    let cases = [
        (
            "reach a by p\n// a comment\n/* and another */\n",
            "reach a by p",
        ),
        (
            "reach a by p { seed 2 } // after\n",
            "reach a by p { seed 2 }",
        ),
        ("map s by p, q   \n\n", "map s by p, q"),
    ];
    for (text, expected) in cases {
        let file = parse(text);
        let Some(Item::Task(task)) = file.items.first() else {
            panic!("{text:?}: not a task")
        };
        let span = task.span;
        assert_eq!(
            &text[span.start as usize..span.end as usize],
            expected,
            "{text:?}"
        );
    }
}
