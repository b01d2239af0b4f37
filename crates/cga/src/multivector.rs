//! The dense multivector and its products.

use crate::blade::{self, ProductKind, BLADE_COUNT, BLADE_NAMES, GRADE_RANGES};
use crate::{generated, CgaError};
use glam::DVec3;
use std::fmt;
use std::ops::{Add, AddAssign, BitOr, BitXor, Div, Index, IndexMut, Mul, Neg, Sub, SubAssign};

/// A multivector of G(4,1): 32 coefficients in canonical blade order
/// (see [`blade`]).
///
/// Operators: `*` geometric product, `^` outer product, `|` inner product (as the Python
/// `clifford` library's `|`), `+`, `-`, scalar `*` and `/`. Index with a canonical blade
/// index to read or write one coefficient.
#[derive(Clone, Copy, PartialEq, Default)]
pub struct Multivector {
    coefficients: [f64; BLADE_COUNT],
}

/// Sign that reversion gives each grade: (−1)^(k(k−1)/2).
const REVERSE_SIGN: [f64; 6] = [1.0, 1.0, -1.0, -1.0, 1.0, 1.0];
/// Sign that grade involution gives each grade: (−1)^k.
const INVOLUTION_SIGN: [f64; 6] = [1.0, -1.0, 1.0, -1.0, 1.0, -1.0];

impl Multivector {
    /// The zero multivector.
    pub const ZERO: Self = Self {
        coefficients: [0.0; BLADE_COUNT],
    };

    /// The scalar 1.
    pub const ONE: Self = Self::scalar(1.0);

    /// A multivector from its 32 coefficients in canonical blade order.
    pub const fn from_coefficients(coefficients: [f64; BLADE_COUNT]) -> Self {
        Self { coefficients }
    }

    /// The 32 coefficients in canonical blade order.
    pub const fn coefficients(&self) -> &[f64; BLADE_COUNT] {
        &self.coefficients
    }

    /// A scalar.
    pub const fn scalar(value: f64) -> Self {
        let mut coefficients = [0.0; BLADE_COUNT];
        coefficients[0] = value;
        Self { coefficients }
    }

    /// The basis blade at canonical index `index` with coefficient 1.
    ///
    /// # Panics
    /// If `index >= 32`.
    pub const fn basis_blade(index: usize) -> Self {
        let mut coefficients = [0.0; BLADE_COUNT];
        coefficients[index] = 1.0;
        Self { coefficients }
    }

    /// The basis blade with the given name (`"e1"`, `"e13"`, `"e12345"`; the factors in
    /// increasing order), or `None`.
    pub fn blade_by_name(name: &str) -> Option<Self> {
        BLADE_NAMES
            .iter()
            .position(|n| *n == name)
            .map(Self::basis_blade)
    }

    /// `e1`, the Euclidean x axis (right).
    pub const fn e1() -> Self {
        Self::basis_blade(1)
    }
    /// `e2`, the Euclidean y axis (up).
    pub const fn e2() -> Self {
        Self::basis_blade(2)
    }
    /// `e3`, the Euclidean z axis (forward).
    pub const fn e3() -> Self {
        Self::basis_blade(3)
    }
    /// `e4`, the conformal basis vector with `e4² = +1`.
    pub const fn e4() -> Self {
        Self::basis_blade(4)
    }
    /// `e5`, the conformal basis vector with `e5² = −1`.
    pub const fn e5() -> Self {
        Self::basis_blade(5)
    }
    /// The null vector representing the origin, `eo = ½(e5 − e4)`.
    pub const fn eo() -> Self {
        let mut c = [0.0; BLADE_COUNT];
        c[4] = -0.5;
        c[5] = 0.5;
        Self { coefficients: c }
    }
    /// The null vector representing infinity, `einf = e4 + e5`.
    pub const fn einf() -> Self {
        let mut c = [0.0; BLADE_COUNT];
        c[4] = 1.0;
        c[5] = 1.0;
        Self { coefficients: c }
    }
    /// The unit pseudoscalar `e12345`.
    pub const fn pseudoscalar() -> Self {
        Self::basis_blade(31)
    }

    /// The Euclidean vector `x e1 + y e2 + z e3`.
    pub const fn from_vector(v: DVec3) -> Self {
        let mut c = [0.0; BLADE_COUNT];
        c[1] = v.x;
        c[2] = v.y;
        c[3] = v.z;
        Self { coefficients: c }
    }

    /// The Euclidean part of the grade-1 part: the `e1, e2, e3` coefficients.
    pub const fn euclidean_vector(&self) -> DVec3 {
        DVec3::new(
            self.coefficients[1],
            self.coefficients[2],
            self.coefficients[3],
        )
    }

    /// The scalar (grade-0) coefficient.
    pub const fn scalar_part(&self) -> f64 {
        self.coefficients[0]
    }

    /// The grade-`k` part; zero for `k > 5`.
    pub fn grade(&self, k: usize) -> Self {
        let mut out = Self::ZERO;
        if let Some(range) = GRADE_RANGES.get(k) {
            out.coefficients[range.clone()].copy_from_slice(&self.coefficients[range.clone()]);
        }
        out
    }

    /// The even part (grades 0, 2, 4).
    pub fn even(&self) -> Self {
        self.grade(0) + self.grade(2) + self.grade(4)
    }

    /// The odd part (grades 1, 3, 5).
    pub fn odd(&self) -> Self {
        *self - self.even()
    }

    /// Whether every odd-grade coefficient is exactly zero (either sign), as for any
    /// product of translators, rotors and dilators. One OR over the bit patterns, cheap
    /// enough for the per-point fast paths; `<< 1` drops the sign bit.
    pub(crate) fn is_even(&self) -> bool {
        const ODD: [usize; 16] = [1, 2, 3, 4, 5, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 31];
        let bits = ODD
            .iter()
            .fold(0u64, |bits, &i| bits | self.coefficients[i].to_bits());
        bits << 1 == 0
    }

    /// The grades with a coefficient whose magnitude exceeds `tolerance`, as a bit set
    /// (bit k set = grade k present).
    pub fn grades_present(&self, tolerance: f64) -> u8 {
        let mut set = 0;
        for (k, range) in GRADE_RANGES.iter().enumerate() {
            if self.coefficients[range.clone()]
                .iter()
                .any(|c| c.abs() > tolerance)
            {
                set |= 1 << k;
            }
        }
        set
    }

    /// Largest coefficient magnitude (the max norm), useful for relative tolerances.
    pub fn max_abs(&self) -> f64 {
        self.coefficients.iter().fold(0.0, |m, c| m.max(c.abs()))
    }

    /// Whether every coefficient is finite.
    pub fn is_finite(&self) -> bool {
        self.coefficients.iter().all(|c| c.is_finite())
    }

    /// Whether every coefficient differs from `other`'s by at most
    /// `tolerance · max(1, |self|∞, |other|∞)`.
    pub fn is_close(&self, other: &Self, tolerance: f64) -> bool {
        let scale = 1f64.max(self.max_abs()).max(other.max_abs());
        self.coefficients
            .iter()
            .zip(&other.coefficients)
            .all(|(a, b)| (a - b).abs() <= tolerance * scale)
    }

    /// The reverse `M̃`: the order of the factors of every blade reversed.
    pub fn reverse(&self) -> Self {
        self.map_by_grade(&REVERSE_SIGN)
    }

    /// The grade involution `M̂`: odd grades negated.
    pub fn grade_involution(&self) -> Self {
        self.map_by_grade(&INVOLUTION_SIGN)
    }

    /// The Clifford conjugate `M̄`: reverse of the grade involution.
    pub fn conjugate(&self) -> Self {
        let mut signs = [0.0; 6];
        for k in 0..6 {
            signs[k] = REVERSE_SIGN[k] * INVOLUTION_SIGN[k];
        }
        self.map_by_grade(&signs)
    }

    fn map_by_grade(&self, signs: &[f64; 6]) -> Self {
        let mut out = *self;
        for (k, range) in GRADE_RANGES.iter().enumerate() {
            for c in &mut out.coefficients[range.clone()] {
                *c *= signs[k];
            }
        }
        out
    }

    /// The outer product `self ∧ other`.
    pub fn outer(&self, other: &Self) -> Self {
        Self::from_coefficients(generated::outer(&self.coefficients, &other.coefficients))
    }

    /// The inner product as the Python `clifford` library's `|` (Hestenes): for blades of
    /// grades r and s, the grade-|r − s| part of their product, and zero when either is a
    /// scalar. For two vectors it is the dot product.
    pub fn inner(&self, other: &Self) -> Self {
        Self::from_coefficients(generated::inner(&self.coefficients, &other.coefficients))
    }

    /// The left contraction `self ⌋ other`.
    pub fn left_contraction(&self, other: &Self) -> Self {
        Self::from_coefficients(generated::left_contraction(
            &self.coefficients,
            &other.coefficients,
        ))
    }

    /// The scalar product `⟨self other⟩₀`.
    pub fn scalar_product(&self, other: &Self) -> f64 {
        // Only equal blades multiply to a scalar.
        (0..BLADE_COUNT)
            .map(|i| self.coefficients[i] * other.coefficients[i] * blade::product(i, i).1)
            .sum()
    }

    /// The squared norm `⟨M M̃⟩₀` (`clifford`'s `mag2`); negative or zero for some
    /// multivectors of this mixed-signature algebra.
    pub fn norm_squared(&self) -> f64 {
        self.scalar_product(&self.reverse())
    }

    /// The norm `√|⟨M M̃⟩₀|` (`clifford`'s `abs`).
    pub fn norm(&self) -> f64 {
        self.norm_squared().abs().sqrt()
    }

    /// The dual `M I⁻¹` with the unit pseudoscalar `I = e12345` (as `clifford`'s `dual`).
    pub fn dual(&self) -> Self {
        // I² = −1, so I⁻¹ = −I.
        *self * (-Self::pseudoscalar())
    }

    /// The inverse `M⁻¹` with `M M⁻¹ = M⁻¹ M = 1`.
    ///
    /// Versors (where `M M̃` is a non-zero scalar) take the fast path `M̃ / (M M̃)`; any other
    /// multivector is inverted by solving the 32×32 linear system of its left
    /// multiplication.
    pub fn inverse(&self) -> Result<Self, CgaError> {
        if !self.is_finite() {
            return Err(CgaError::NotFinite(self.to_string()));
        }
        let reverse = self.reverse();
        let product = *self * reverse;
        let scale = product.max_abs();
        if scale > 0.0 {
            let non_scalar = (product - Self::scalar(product.scalar_part())).max_abs();
            if non_scalar <= 1e-12 * scale && product.scalar_part().abs() > 1e-300 {
                return Ok(reverse / product.scalar_part());
            }
        }
        self.inverse_by_linear_system()
    }

    // Rows and columns are blade indices of the algebra; index loops read clearest here.
    #[allow(clippy::needless_range_loop)]
    fn inverse_by_linear_system(&self) -> Result<Self, CgaError> {
        // Column j of the matrix is self * e_j, so solving L x = 1 gives self * x = 1.
        let mut m = [[0.0f64; BLADE_COUNT + 1]; BLADE_COUNT];
        for (i, &a) in self.coefficients.iter().enumerate() {
            if a == 0.0 {
                continue;
            }
            for j in 0..BLADE_COUNT {
                let (k, sign) = blade::product(i, j);
                m[k][j] += sign * a;
            }
        }
        m[0][BLADE_COUNT] = 1.0;
        let largest = m
            .iter()
            .flat_map(|row| row[..BLADE_COUNT].iter())
            .fold(0.0f64, |acc, v| acc.max(v.abs()));
        let not_invertible = || CgaError::NotInvertible(self.to_string());
        if largest == 0.0 {
            return Err(not_invertible());
        }
        for col in 0..BLADE_COUNT {
            let pivot = (col..BLADE_COUNT)
                .max_by(|&a, &b| m[a][col].abs().total_cmp(&m[b][col].abs()))
                .unwrap_or(col);
            if m[pivot][col].abs() <= 1e-12 * largest {
                return Err(not_invertible());
            }
            m.swap(col, pivot);
            for row in 0..BLADE_COUNT {
                if row != col {
                    let factor = m[row][col] / m[col][col];
                    if factor != 0.0 {
                        for k in col..=BLADE_COUNT {
                            m[row][k] -= factor * m[col][k];
                        }
                    }
                }
            }
        }
        let mut out = Self::ZERO;
        for (i, row) in m.iter().enumerate() {
            out.coefficients[i] = row[BLADE_COUNT] / row[i];
        }
        if !(*self * out).is_close(&Self::ONE, 1e-8) {
            return Err(not_invertible());
        }
        Ok(out)
    }

    /// The sandwich product `self X self⁻¹`: how the versor `self` transforms `x`.
    pub fn sandwich(&self, x: &Self) -> Result<Self, CgaError> {
        Ok(*self * *x * self.inverse()?)
    }

    /// Integer power by repeated multiplication; negative powers use the inverse.
    pub fn powi(&self, exponent: i32) -> Result<Self, CgaError> {
        let base = if exponent < 0 { self.inverse()? } else { *self };
        let mut result = Self::ONE;
        let mut square = base;
        let mut n = exponent.unsigned_abs();
        while n > 0 {
            if n & 1 == 1 {
                result = result * square;
            }
            square = square * square;
            n >>= 1;
        }
        Ok(result)
    }

    /// Product of `self` with `other` by blade table, without the generated kernels; the
    /// reference the kernels are tested against.
    pub fn product_by_table(&self, other: &Self, kind: ProductKind) -> Self {
        let mut out = Self::ZERO;
        for (i, &a) in self.coefficients.iter().enumerate() {
            for (j, &b) in other.coefficients.iter().enumerate() {
                if kind.keeps(i, j) {
                    let (k, sign) = blade::product(i, j);
                    out.coefficients[k] += sign * a * b;
                }
            }
        }
        out
    }

    /// The geometric product of two even multivectors (versors), reading and writing only
    /// the even blades: half the work of `*`. For odd inputs the result is wrong; use `*`.
    #[must_use]
    pub fn geometric_even_even(&self, other: &Self) -> Self {
        Self::from_coefficients(generated::geometric_even_even(
            &self.coefficients,
            &other.coefficients,
        ))
    }
}

impl Index<usize> for Multivector {
    type Output = f64;
    fn index(&self, index: usize) -> &f64 {
        &self.coefficients[index]
    }
}

impl IndexMut<usize> for Multivector {
    fn index_mut(&mut self, index: usize) -> &mut f64 {
        &mut self.coefficients[index]
    }
}

impl Mul for Multivector {
    type Output = Self;
    /// The geometric product.
    #[inline]
    fn mul(self, rhs: Self) -> Self {
        Self::from_coefficients(crate::dispatch::geometric(
            &self.coefficients,
            &rhs.coefficients,
        ))
    }
}

impl Mul<f64> for Multivector {
    type Output = Self;
    fn mul(mut self, rhs: f64) -> Self {
        self.coefficients.iter_mut().for_each(|c| *c *= rhs);
        self
    }
}

impl Mul<Multivector> for f64 {
    type Output = Multivector;
    fn mul(self, rhs: Multivector) -> Multivector {
        rhs * self
    }
}

impl Div<f64> for Multivector {
    type Output = Self;
    fn div(mut self, rhs: f64) -> Self {
        self.coefficients.iter_mut().for_each(|c| *c /= rhs);
        self
    }
}

impl BitXor for Multivector {
    type Output = Self;
    /// The outer product.
    fn bitxor(self, rhs: Self) -> Self {
        self.outer(&rhs)
    }
}

impl BitOr for Multivector {
    type Output = Self;
    /// The inner product (as `clifford`'s `|`).
    fn bitor(self, rhs: Self) -> Self {
        self.inner(&rhs)
    }
}

impl Add for Multivector {
    type Output = Self;
    fn add(mut self, rhs: Self) -> Self {
        self += rhs;
        self
    }
}

impl AddAssign for Multivector {
    fn add_assign(&mut self, rhs: Self) {
        for (a, b) in self.coefficients.iter_mut().zip(rhs.coefficients) {
            *a += b;
        }
    }
}

impl Sub for Multivector {
    type Output = Self;
    fn sub(mut self, rhs: Self) -> Self {
        self -= rhs;
        self
    }
}

impl SubAssign for Multivector {
    fn sub_assign(&mut self, rhs: Self) {
        for (a, b) in self.coefficients.iter_mut().zip(rhs.coefficients) {
            *a -= b;
        }
    }
}

impl Neg for Multivector {
    type Output = Self;
    fn neg(self) -> Self {
        self * -1.0
    }
}

impl fmt::Display for Multivector {
    /// Written as a sum of blades, e.g. `1 + 0.5 e1 - 2 e45`; zero is `0`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut first = true;
        for (i, &c) in self.coefficients.iter().enumerate() {
            if c == 0.0 {
                continue;
            }
            let magnitude = c.abs();
            let sign = if c < 0.0 { "-" } else { "+" };
            match (first, c < 0.0) {
                (true, false) => {}
                (true, true) => f.write_str("-")?,
                (false, _) => write!(f, " {sign} ")?,
            }
            if i == 0 {
                write!(f, "{magnitude}")?;
            } else {
                write!(f, "{magnitude} {}", BLADE_NAMES[i])?;
            }
            first = false;
        }
        if first {
            f.write_str("0")?;
        }
        Ok(())
    }
}

impl fmt::Debug for Multivector {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Multivector({self})")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn display() {
        let m = Multivector::scalar(1.0) + Multivector::e1() * 0.5 - Multivector::e4() * 2.0;
        assert_eq!(m.to_string(), "1 + 0.5 e1 - 2 e4");
        assert_eq!(Multivector::ZERO.to_string(), "0");
        assert_eq!((-Multivector::e2()).to_string(), "-1 e2");
    }

    #[test]
    fn kernels_match_blade_table() {
        let a = Multivector::from_coefficients(std::array::from_fn(|i| (i as f64 * 0.37).sin()));
        let b = Multivector::from_coefficients(std::array::from_fn(|i| (i as f64 * 0.91).cos()));
        assert!((a * b).is_close(&a.product_by_table(&b, ProductKind::Geometric), 1e-14));
        assert_eq!(a ^ b, a.product_by_table(&b, ProductKind::Outer));
        assert_eq!(a | b, a.product_by_table(&b, ProductKind::Inner));
        assert_eq!(
            a.left_contraction(&b),
            a.product_by_table(&b, ProductKind::LeftContraction)
        );
        let (ea, eb) = (a.even(), b.even());
        assert!(ea.geometric_even_even(&eb).is_close(&(ea * eb), 1e-14));
        // The CPU-dispatched kernel rounds exactly as the baseline one.
        assert_eq!(
            crate::dispatch::geometric(&a.coefficients, &b.coefficients),
            generated::geometric(&a.coefficients, &b.coefficients)
        );
    }

    #[test]
    fn involutions() {
        let e12 = Multivector::blade_by_name("e12").unwrap();
        assert_eq!(e12.reverse(), -e12);
        assert_eq!(e12.grade_involution(), e12);
        assert_eq!(e12.conjugate(), -e12);
        assert_eq!(Multivector::e1().conjugate(), -Multivector::e1());
        assert_eq!(Multivector::e1().reverse(), Multivector::e1());
    }

    #[test]
    fn inner_product_of_scalar_is_zero_like_clifford() {
        let s = Multivector::scalar(2.0);
        assert_eq!(s | Multivector::e1(), Multivector::ZERO);
        assert_eq!(Multivector::e1() | Multivector::e1(), Multivector::ONE);
        assert_eq!(
            s.left_contraction(&Multivector::e1()),
            Multivector::e1() * 2.0
        );
    }

    #[test]
    fn null_vectors() {
        assert_eq!((Multivector::eo() * Multivector::eo()).max_abs(), 0.0);
        assert_eq!((Multivector::einf() * Multivector::einf()).max_abs(), 0.0);
        assert_eq!(
            (Multivector::einf() | Multivector::eo()).scalar_part(),
            -1.0
        );
    }

    #[test]
    fn inverse_of_non_invertible_is_an_error() {
        assert!(Multivector::einf().inverse().is_err());
        assert!(Multivector::ZERO.inverse().is_err());
        let one_plus_e1 = Multivector::ONE + Multivector::e1();
        assert!(one_plus_e1.inverse().is_err());
    }

    #[test]
    fn inverse_general_and_versor() {
        let a = Multivector::from_coefficients(std::array::from_fn(|i| 1.0 / (i as f64 + 2.0)));
        let inv = a.inverse().unwrap();
        assert!((a * inv).is_close(&Multivector::ONE, 1e-9));
        assert!((inv * a).is_close(&Multivector::ONE, 1e-9));
        let v = Multivector::e1() * 2.0;
        assert!(v
            .inverse()
            .unwrap()
            .is_close(&(Multivector::e1() * 0.5), 1e-15));
    }

    #[test]
    fn integer_powers() {
        let e12 = Multivector::blade_by_name("e12").unwrap();
        assert_eq!(e12.powi(2).unwrap(), -Multivector::ONE);
        assert_eq!(e12.powi(0).unwrap(), Multivector::ONE);
        assert!(e12.powi(-1).unwrap().is_close(&-e12, 1e-15));
    }
}
