//! The 32 basis blades of G(4,1) and the rules for multiplying them.
//!
//! A blade is stored as a bit mask: bit `i` set means the factor `e(i+1)` is present, so
//! `e13` is `0b00101`. Multivector coefficients are stored in the *canonical order* used by
//! the Python `clifford` library: grade by grade, lexicographic inside a grade
//! (`1, e1 … e5, e12, e13, … e45, e123, … e12345`).

/// Number of basis blades (2⁵).
pub const BLADE_COUNT: usize = 32;

/// Number of basis vectors (e1 … e5).
pub const BASIS_COUNT: usize = 5;

/// Square of each basis vector: e1² = e2² = e3² = e4² = +1, e5² = −1.
pub const METRIC: [f64; BASIS_COUNT] = [1.0, 1.0, 1.0, 1.0, -1.0];

/// Names of the blades in canonical order.
pub const BLADE_NAMES: [&str; BLADE_COUNT] = [
    "1", "e1", "e2", "e3", "e4", "e5", "e12", "e13", "e14", "e15", "e23", "e24", "e25", "e34",
    "e35", "e45", "e123", "e124", "e125", "e134", "e135", "e145", "e234", "e235", "e245", "e345",
    "e1234", "e1235", "e1245", "e1345", "e2345", "e12345",
];

/// Bit mask of each blade, in canonical order.
pub const BLADE_MASKS: [u8; BLADE_COUNT] = [
    0b00000, // 1
    0b00001, 0b00010, 0b00100, 0b01000, 0b10000, // e1 … e5
    0b00011, 0b00101, 0b01001, 0b10001, 0b00110, 0b01010, 0b10010, 0b01100, 0b10100,
    0b11000, // e12 … e45
    0b00111, 0b01011, 0b10011, 0b01101, 0b10101, 0b11001, 0b01110, 0b10110, 0b11010,
    0b11100, // e123 … e345
    0b01111, 0b10111, 0b11011, 0b11101, 0b11110, // e1234 … e2345
    0b11111, // e12345
];

/// Canonical index of each bit mask (the inverse of [`BLADE_MASKS`]).
pub const MASK_TO_INDEX: [usize; BLADE_COUNT] = invert_masks();

const fn invert_masks() -> [usize; BLADE_COUNT] {
    let mut table = [0usize; BLADE_COUNT];
    let mut i = 0;
    while i < BLADE_COUNT {
        table[BLADE_MASKS[i] as usize] = i;
        i += 1;
    }
    table
}

/// Grade (number of basis-vector factors) of the blade at canonical index `index`.
pub const fn grade(index: usize) -> u32 {
    BLADE_MASKS[index].count_ones()
}

/// Canonical index range of each grade: `GRADE_RANGES[k]` holds the blades of grade `k`.
pub const GRADE_RANGES: [core::ops::Range<usize>; BASIS_COUNT + 1] =
    [0..1, 1..6, 6..16, 16..26, 26..31, 31..32];

/// Sign from reordering the product of two blades given as bit masks into canonical form,
/// without the metric: each basis vector of `b` that has to move past one of `a` flips it.
pub const fn reorder_sign(a: u8, b: u8) -> f64 {
    let mut a = a >> 1;
    let mut swaps = 0;
    while a != 0 {
        swaps += (a & b).count_ones();
        a >>= 1;
    }
    if swaps % 2 == 0 {
        1.0
    } else {
        -1.0
    }
}

/// Geometric product of two basis blades given by canonical index.
///
/// Returns the canonical index of the resulting blade and its sign (±1), metric included.
pub const fn product(a: usize, b: usize) -> (usize, f64) {
    let ma = BLADE_MASKS[a];
    let mb = BLADE_MASKS[b];
    let mut sign = reorder_sign(ma, mb);
    let common = ma & mb;
    let mut bit = 0;
    while bit < BASIS_COUNT {
        if common & (1 << bit) != 0 {
            sign *= METRIC[bit];
        }
        bit += 1;
    }
    (MASK_TO_INDEX[(ma ^ mb) as usize], sign)
}

/// The products the algebra defines, each a filter on the blade-by-blade geometric product.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ProductKind {
    /// The geometric product `ab`.
    Geometric,
    /// The outer (wedge) product `a ∧ b`: the terms with no common factor.
    Outer,
    /// The inner product of the Python `clifford` library (`|`, Hestenes' inner product):
    /// the grade `|r − s|` part of the product of an r-blade and an s-blade, and zero when
    /// either is a scalar. For two vectors it is the dot product.
    Inner,
    /// The left contraction `a ⌋ b`: the grade `s − r` part, zero when r > s.
    LeftContraction,
}

impl ProductKind {
    /// Whether the product keeps the term from blades `a` and `b` (canonical indices).
    pub const fn keeps(self, a: usize, b: usize) -> bool {
        let ga = grade(a);
        let gb = grade(b);
        let gr = (BLADE_MASKS[a] ^ BLADE_MASKS[b]).count_ones();
        match self {
            ProductKind::Geometric => true,
            ProductKind::Outer => BLADE_MASKS[a] & BLADE_MASKS[b] == 0,
            ProductKind::Inner => ga != 0 && gb != 0 && gr == ga.abs_diff(gb),
            ProductKind::LeftContraction => ga <= gb && gr == gb - ga,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn masks_match_names_and_canonical_order() {
        for (i, name) in BLADE_NAMES.iter().enumerate() {
            let mut mask = 0u8;
            for c in name.trim_start_matches('e').chars() {
                if c != '1' || *name != "1" {
                    mask |= 1 << (c.to_digit(10).unwrap() - 1);
                }
            }
            assert_eq!(BLADE_MASKS[i], mask, "{name}");
        }
        for i in 1..BLADE_COUNT {
            let (a, b) = (BLADE_MASKS[i - 1], BLADE_MASKS[i]);
            // Grade by grade; inside a grade, lexicographic on the factor list.
            let key = |m: u8| {
                let factors: Vec<u32> = (0..5).filter(|k| m & (1 << k) != 0).collect();
                (factors.len(), factors)
            };
            assert!(
                key(a) < key(b),
                "{} before {}",
                BLADE_NAMES[i - 1],
                BLADE_NAMES[i]
            );
        }
        for (k, range) in GRADE_RANGES.iter().enumerate() {
            assert!(range.clone().all(|i| grade(i) == k as u32));
        }
    }

    #[test]
    fn basis_products() {
        let e = |n: &str| BLADE_NAMES.iter().position(|b| *b == n).unwrap();
        assert_eq!(product(e("e1"), e("e2")), (e("e12"), 1.0));
        assert_eq!(product(e("e2"), e("e1")), (e("e12"), -1.0));
        assert_eq!(product(e("e5"), e("e5")), (0, -1.0));
        assert_eq!(product(e("e4"), e("e4")), (0, 1.0));
        assert_eq!(product(e("e12"), e("e12")), (0, -1.0));
        assert_eq!(product(e("e12345"), e("e12345")), (0, -1.0));
        assert_eq!(product(e("e13"), e("e3")), (e("e1"), 1.0));
    }
}
