//! Bounds on what one scenario may ask of the tool, so that hostile or
//! broken input gets a diagnostic instead of exhausting the stack or the
//! memory. Each is documented in docs/language.md.

/// Largest file read, in bytes.
pub const MAX_FILE_BYTES: u64 = 16 * 1024 * 1024;

/// Deepest nesting of parentheses and braces (expressions, points, option
/// blocks), counted together.
pub const MAX_PAREN_DEPTH: usize = 64;

/// Most operands and operators in one expression (a sum of 300 terms is
/// already far beyond any scenario).
pub const MAX_EXPR_TOKENS: usize = 1024;

/// Longest chain of constants defined in terms of each other.
pub const MAX_LET_DEPTH: usize = 256;

/// Longest chain of files using each other.
pub const MAX_USE_DEPTH: usize = 64;
