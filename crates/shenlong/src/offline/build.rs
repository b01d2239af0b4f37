//! Building answers as expression trees (`crate::expr::Expr`): the offline translator
//! writes typed trees, and the reply it reports is printed from them.

use crate::expr::{BinaryOp, Expr, ExprKind, UnaryOp};

fn node(kind: ExprKind) -> Expr {
    Expr { kind, span: 0..0 }
}

/// A number.
pub(crate) fn num(x: f64) -> Expr {
    node(ExprKind::Number(x))
}

/// A name: `e1`, `pi`, `room`.
pub(crate) fn name(n: &str) -> Expr {
    node(ExprKind::Name(n.to_string()))
}

/// The basis vector of an axis (0 = e1, 1 = e2, 2 = e3).
pub(crate) fn axis(a: usize) -> Expr {
    name(["e1", "e2", "e3"][a])
}

/// `base.attribute`.
pub(crate) fn attr(base: Expr, attribute: &str) -> Expr {
    node(ExprKind::Attribute(Box::new(base), attribute.to_string()))
}

/// `X{k+1}.attribute`.
pub(crate) fn var(k: usize, attribute: &str) -> Expr {
    attr(name(&format!("X{}", k + 1)), attribute)
}

/// `room.attribute`.
pub(crate) fn room(attribute: &str) -> Expr {
    attr(name("room"), attribute)
}

fn bin(op: BinaryOp, a: Expr, b: Expr) -> Expr {
    node(ExprKind::Binary(op, Box::new(a), Box::new(b)))
}

/// `a + b`.
pub(crate) fn add(a: Expr, b: Expr) -> Expr {
    bin(BinaryOp::Add, a, b)
}

/// `a - b`.
pub(crate) fn sub(a: Expr, b: Expr) -> Expr {
    bin(BinaryOp::Sub, a, b)
}

/// `a * b`.
pub(crate) fn mul(a: Expr, b: Expr) -> Expr {
    bin(BinaryOp::Mul, a, b)
}

/// `a / b`.
pub(crate) fn div(a: Expr, b: Expr) -> Expr {
    bin(BinaryOp::Div, a, b)
}

/// `a | b`, the inner product: a vector's coordinate along a basis vector.
pub(crate) fn dot(a: Expr, b: Expr) -> Expr {
    bin(BinaryOp::Inner, a, b)
}

/// `-a`.
pub(crate) fn neg(a: Expr) -> Expr {
    node(ExprKind::Unary(UnaryOp::Neg, Box::new(a)))
}

/// `~a`, the reverse (the inverse of a rotor).
pub(crate) fn reverse(a: Expr) -> Expr {
    node(ExprKind::Unary(UnaryOp::Reverse, Box::new(a)))
}

/// `f(arguments…)`.
pub(crate) fn call(f: &str, arguments: Vec<Expr>) -> Expr {
    node(ExprKind::Call(Box::new(name(f)), arguments))
}

/// The sum of several terms (`0` for none).
pub(crate) fn sum(terms: impl IntoIterator<Item = Expr>) -> Expr {
    terms.into_iter().reduce(add).unwrap_or_else(|| num(0.0))
}

/// `(v | e) * e`: the part of a vector along an axis.
pub(crate) fn along(v: Expr, a: usize) -> Expr {
    mul(dot(v, axis(a)), axis(a))
}

/// `x * e`: a scalar along an axis.
pub(crate) fn scaled_axis(x: Expr, a: usize) -> Expr {
    mul(x, axis(a))
}

/// The horizontal part of a vector (x and z).
pub(crate) fn flat(v: Expr) -> Expr {
    add(along(v.clone(), 0), along(v, 2))
}

/// `1` when `x > 0`, else `0` (ties go to 1): `(1 + (x + ε) / abs(x + ε)) / 2`.
pub(crate) fn step(x: Expr) -> Expr {
    let shifted = add(x, num(1e-12));
    div(
        add(num(1.0), div(shifted.clone(), call("abs", vec![shifted]))),
        num(2.0),
    )
}

/// `T(v)`.
pub(crate) fn translator(v: Expr) -> Expr {
    call("T", vec![v])
}

/// `R(angle, u, v)`.
pub(crate) fn rotor(angle: Expr, plane: (usize, usize)) -> Expr {
    call("R", vec![angle, axis(plane.0), axis(plane.1)])
}

/// `D(s)`.
pub(crate) fn dilator(s: f64) -> Expr {
    call("D", vec![num(s)])
}

/// Degrees as radians: `d * pi / 180`.
pub(crate) fn degrees(d: f64) -> Expr {
    div(mul(num(d), name("pi")), num(180.0))
}
