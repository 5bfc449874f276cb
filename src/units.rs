//! Units and dimensions. Numbers in `.reach` files are lengths, angles or
//! plain numbers; internally lengths are millimetres and angles radians.
//! A number written without a unit is *bare*: it takes the file's default
//! unit of whatever kind the place it is used in expects (`units mm deg`).

use std::fmt;

/// A unit a number can be written in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Unit {
    Mm,
    Cm,
    M,
    In,
    Deg,
    Rad,
    Arcmin,
    /// `%`: a share; a number without unit, divided by 100. Written only
    /// after a number, never in `units`.
    Percent,
}

impl Unit {
    pub const ALL: [Unit; 7] = [
        Unit::Mm,
        Unit::Cm,
        Unit::M,
        Unit::In,
        Unit::Deg,
        Unit::Rad,
        Unit::Arcmin,
    ];

    pub fn parse(text: &str) -> Option<Unit> {
        Unit::ALL.into_iter().find(|u| u.symbol() == text)
    }

    pub fn symbol(self) -> &'static str {
        match self {
            Unit::Mm => "mm",
            Unit::Cm => "cm",
            Unit::M => "m",
            Unit::In => "in",
            Unit::Deg => "deg",
            Unit::Rad => "rad",
            Unit::Arcmin => "arcmin",
            Unit::Percent => "%",
        }
    }

    pub fn is_length(self) -> bool {
        matches!(self, Unit::Mm | Unit::Cm | Unit::M | Unit::In)
    }

    /// The factor to millimetres (lengths) or radians (angles).
    pub fn to_internal(self) -> f64 {
        match self {
            Unit::Mm => 1.0,
            Unit::Cm => 10.0,
            Unit::M => 1000.0,
            Unit::In => 25.4,
            Unit::Deg => std::f64::consts::PI / 180.0,
            Unit::Rad => 1.0,
            Unit::Arcmin => std::f64::consts::PI / (180.0 * 60.0),
            Unit::Percent => 0.01,
        }
    }

    pub fn dim(self) -> Dim {
        if self == Unit::Percent {
            Dim::NONE
        } else if self.is_length() {
            Dim::LENGTH
        } else {
            Dim::ANGLE
        }
    }
}

/// The units bare numbers take in one file.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct UnitDefaults {
    pub length: Unit,
    pub angle: Unit,
}

impl Default for UnitDefaults {
    fn default() -> Self {
        UnitDefaults {
            length: Unit::Mm,
            angle: Unit::Deg,
        }
    }
}

/// A physical dimension: powers of length and angle. Dimensionless is (0, 0).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Dim {
    pub length: i8,
    pub angle: i8,
}

impl Dim {
    pub const NONE: Dim = Dim {
        length: 0,
        angle: 0,
    };
    pub const LENGTH: Dim = Dim {
        length: 1,
        angle: 0,
    };
    pub const ANGLE: Dim = Dim {
        length: 0,
        angle: 1,
    };

    fn times(self, o: Dim) -> Dim {
        Dim {
            length: self.length.saturating_add(o.length),
            angle: self.angle.saturating_add(o.angle),
        }
    }

    fn per(self, o: Dim) -> Dim {
        Dim {
            length: self.length.saturating_sub(o.length),
            angle: self.angle.saturating_sub(o.angle),
        }
    }
}

impl fmt::Display for Dim {
    /// With an article, as in "expected a length, found an angle".
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (self.length, self.angle) {
            (0, 0) => write!(f, "a number without unit"),
            (1, 0) => write!(f, "a length"),
            (0, 1) => write!(f, "an angle"),
            (2, 0) => write!(f, "an area"),
            (l, a) => write!(f, "a quantity of unit mm^{l} rad^{a}"),
        }
    }
}

/// The value of an expression: internal units (mm, rad) when it has a
/// dimension, or a bare number still waiting for one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Quantity {
    Bare { value: f64, defaults: UnitDefaults },
    Dimensioned { value: f64, dim: Dim },
}

/// Why two quantities could not be combined.
#[derive(Clone, Debug, PartialEq)]
pub enum QuantityError {
    Operands {
        verb: &'static str,
        left: String,
        right: String,
    },
    DivisionByZero,
    MixedDefaults,
}

impl Quantity {
    pub fn dimensioned(value: f64, dim: Dim) -> Self {
        Quantity::Dimensioned { value, dim }
    }

    pub fn describe(&self) -> String {
        match self {
            Quantity::Bare { .. } => "a number without unit".to_string(),
            Quantity::Dimensioned { dim, .. } => dim.to_string(),
        }
    }

    pub fn negated(self) -> Self {
        match self {
            Quantity::Bare { value, defaults } => Quantity::Bare {
                value: -value,
                defaults,
            },
            Quantity::Dimensioned { value, dim } => Quantity::Dimensioned { value: -value, dim },
        }
    }

    /// `self + other` (or minus, with `sign` -1). A bare number added to a
    /// length is a length in the file's default length unit.
    pub fn sum(self, other: Quantity, sign: f64) -> Result<Quantity, QuantityError> {
        use Quantity::*;
        let verb = if sign > 0.0 { "add" } else { "subtract" };
        match (self, other) {
            (
                Bare {
                    value: a,
                    defaults: da,
                },
                Bare {
                    value: b,
                    defaults: db,
                },
            ) => both_bare(a, da, b, db, |x, y| x + sign * y),
            (Dimensioned { value: a, dim }, Bare { value: b, defaults }) if adopts(dim) => {
                Ok(Dimensioned {
                    value: a + sign * b * default_factor(dim, defaults),
                    dim,
                })
            }
            (Bare { value: a, defaults }, Dimensioned { value: b, dim }) if adopts(dim) => {
                Ok(Dimensioned {
                    value: a * default_factor(dim, defaults) + sign * b,
                    dim,
                })
            }
            (Dimensioned { value: a, dim: da }, Dimensioned { value: b, dim: db }) if da == db => {
                Ok(Dimensioned {
                    value: a + sign * b,
                    dim: da,
                })
            }
            (l, r) => Err(QuantityError::Operands {
                verb,
                left: l.describe(),
                right: r.describe(),
            }),
        }
    }

    /// `self * other`: a bare number in a product is a plain factor.
    pub fn product(self, other: Quantity) -> Result<Quantity, QuantityError> {
        use Quantity::*;
        Ok(match (self, other) {
            (
                Bare {
                    value: a,
                    defaults: da,
                },
                Bare {
                    value: b,
                    defaults: db,
                },
            ) => {
                return both_bare(a, da, b, db, |x, y| x * y);
            }
            (Bare { value: a, .. }, Dimensioned { value: b, dim })
            | (Dimensioned { value: b, dim }, Bare { value: a, .. }) => {
                Dimensioned { value: a * b, dim }
            }
            (Dimensioned { value: a, dim: da }, Dimensioned { value: b, dim: db }) => Dimensioned {
                value: a * b,
                dim: da.times(db),
            },
        })
    }

    /// `self / other`.
    pub fn quotient(self, other: Quantity) -> Result<Quantity, QuantityError> {
        use Quantity::*;
        if other.raw() == 0.0 {
            return Err(QuantityError::DivisionByZero);
        }
        Ok(match (self, other) {
            (
                Bare {
                    value: a,
                    defaults: da,
                },
                Bare {
                    value: b,
                    defaults: db,
                },
            ) => {
                return both_bare(a, da, b, db, |x, y| x / y);
            }
            (Dimensioned { value: a, dim }, Bare { value: b, .. }) => {
                Dimensioned { value: a / b, dim }
            }
            (Bare { value: a, .. }, Dimensioned { value: b, dim }) => Dimensioned {
                value: a / b,
                dim: Dim::NONE.per(dim),
            },
            (Dimensioned { value: a, dim: da }, Dimensioned { value: b, dim: db }) => Dimensioned {
                value: a / b,
                dim: da.per(db),
            },
        })
    }

    /// Nothing of this kind: a bare 0, or 0 of this dimension.
    pub fn zero(self) -> Quantity {
        match self {
            Quantity::Bare { defaults, .. } => Quantity::Bare {
                value: 0.0,
                defaults,
            },
            Quantity::Dimensioned { dim, .. } => Quantity::Dimensioned { value: 0.0, dim },
        }
    }

    /// The number as stored, without regard to its unit.
    pub fn raw(&self) -> f64 {
        match self {
            Quantity::Bare { value, .. } | Quantity::Dimensioned { value, .. } => *value,
        }
    }

    /// The value in internal units (mm, rad) if it is of dimension `want`;
    /// a bare number takes its file's default unit for that dimension.
    pub fn as_dim(&self, want: Dim) -> Option<f64> {
        match *self {
            Quantity::Bare { value, defaults } => Some(value * default_factor(want, defaults)),
            Quantity::Dimensioned { value, dim } if dim == want => Some(value),
            _ => None,
        }
    }
}

/// Two bare numbers combine into a bare number, if their files agree on
/// default units.
fn both_bare(
    a: f64,
    da: UnitDefaults,
    b: f64,
    db: UnitDefaults,
    op: impl FnOnce(f64, f64) -> f64,
) -> Result<Quantity, QuantityError> {
    if da != db {
        return Err(QuantityError::MixedDefaults);
    }
    Ok(Quantity::Bare {
        value: op(a, b),
        defaults: da,
    })
}

/// Whether a bare number added to a quantity of this dimension can take the
/// file's default unit (lengths, angles and plain numbers can).
fn adopts(dim: Dim) -> bool {
    dim == Dim::LENGTH || dim == Dim::ANGLE || dim == Dim::NONE
}

fn default_factor(dim: Dim, defaults: UnitDefaults) -> f64 {
    if dim == Dim::LENGTH {
        defaults.length.to_internal()
    } else if dim == Dim::ANGLE {
        defaults.angle.to_internal()
    } else {
        1.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bare(v: f64) -> Quantity {
        Quantity::Bare {
            value: v,
            defaults: UnitDefaults::default(),
        }
    }
    fn len(v: f64) -> Quantity {
        Quantity::dimensioned(v, Dim::LENGTH)
    }
    fn ang(v: f64) -> Quantity {
        Quantity::dimensioned(v, Dim::ANGLE)
    }

    #[test]
    fn bare_plus_length_takes_the_default_length_unit() {
        let cm = UnitDefaults {
            length: Unit::Cm,
            angle: Unit::Deg,
        };
        let q = len(900.0)
            .sum(
                Quantity::Bare {
                    value: 6.0,
                    defaults: cm,
                },
                1.0,
            )
            .unwrap();
        assert_eq!(q, len(960.0));
    }

    #[test]
    fn bare_times_length_is_a_scaled_length() {
        assert_eq!(bare(2.0).product(len(300.0)).unwrap(), len(600.0));
        assert_eq!(len(300.0).quotient(bare(2.0)).unwrap(), len(150.0));
    }

    #[test]
    fn length_over_length_is_a_plain_number() {
        let q = len(300.0).quotient(len(600.0)).unwrap();
        assert_eq!(q.as_dim(Dim::NONE), Some(0.5));
        assert_eq!(q.as_dim(Dim::LENGTH), None);
    }

    #[test]
    fn adding_length_and_angle_is_an_error() {
        let e = len(1.0).sum(ang(1.0), 1.0).unwrap_err();
        assert_eq!(
            e,
            QuantityError::Operands {
                verb: "add",
                left: "a length".into(),
                right: "an angle".into()
            }
        );
        assert!(len(1.0).sum(ang(1.0), -1.0).is_err());
    }

    #[test]
    fn division_by_zero_is_an_error() {
        assert_eq!(
            len(1.0).quotient(bare(0.0)),
            Err(QuantityError::DivisionByZero)
        );
    }

    #[test]
    fn bare_numbers_resolve_by_the_expected_dimension() {
        let q = bare(90.0);
        assert!((q.as_dim(Dim::ANGLE).unwrap() - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
        assert_eq!(q.as_dim(Dim::LENGTH), Some(90.0));
        assert_eq!(q.as_dim(Dim::NONE), Some(90.0));
    }

    #[test]
    fn units_convert_to_millimetres_and_radians() {
        assert_eq!(Unit::In.to_internal(), 25.4);
        assert_eq!(Unit::M.to_internal(), 1000.0);
        let arcmin_in_deg = Unit::Arcmin.to_internal() / Unit::Deg.to_internal();
        assert!((arcmin_in_deg - 1.0 / 60.0).abs() < 1e-15);
    }

    #[test]
    fn area_is_not_a_length() {
        let area = len(2.0).product(len(3.0)).unwrap();
        assert_eq!(area.describe(), "an area");
        assert_eq!(area.as_dim(Dim::LENGTH), None);
    }

    #[test]
    fn bare_numbers_from_different_files_do_not_mix() {
        let m = Quantity::Bare {
            value: 1.0,
            defaults: UnitDefaults {
                length: Unit::M,
                angle: Unit::Deg,
            },
        };
        assert_eq!(bare(1.0).sum(m, 1.0), Err(QuantityError::MixedDefaults));
    }
}
