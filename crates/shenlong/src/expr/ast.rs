//! The syntax tree of an expression.

use super::error::Span;
use std::fmt;

/// A node of the syntax tree, with the text it came from.
#[derive(Clone, Debug)]
pub struct Expr {
    /// What the node is.
    pub kind: ExprKind,
    /// Where it is in the text.
    pub span: Span,
}

/// Equality of structure; spans are ignored, so a printed and re-parsed tree equals the
/// original.
impl PartialEq for Expr {
    fn eq(&self, other: &Self) -> bool {
        self.kind == other.kind
    }
}

/// The kinds of node.
#[derive(Clone, Debug, PartialEq)]
pub enum ExprKind {
    /// A number literal.
    Number(f64),
    /// A name: a blade, a constant, a variable, a function or a module (`np`).
    Name(String),
    /// `base.name`: `X1.max`, `np.pi`.
    Attribute(Box<Expr>, String),
    /// `callee(arguments…)`.
    Call(Box<Expr>, Vec<Expr>),
    /// `base[index]` (the Euclidean dialect).
    Index(Box<Expr>, Box<Expr>),
    /// A prefix operator.
    Unary(UnaryOp, Box<Expr>),
    /// An infix operator.
    Binary(BinaryOp, Box<Expr>, Box<Expr>),
}

/// Prefix operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UnaryOp {
    /// `-x`
    Neg,
    /// `+x`
    Plus,
    /// `~x`, the reverse.
    Reverse,
}

/// Infix operators, from lowest to highest precedence as in Python.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinaryOp {
    /// `a | b`, the inner product.
    Inner,
    /// `a ^ b`, the outer product.
    Outer,
    /// `a + b`
    Add,
    /// `a - b`
    Sub,
    /// `a * b`, the geometric product.
    Mul,
    /// `a @ b`, the matrix product (the Euclidean dialect; composition, as `*` of versors).
    MatMul,
    /// `a / b`, division by a number.
    Div,
    /// `a ** n`, an integer power.
    Pow,
}

impl BinaryOp {
    /// The operator as written.
    pub fn symbol(self) -> &'static str {
        match self {
            BinaryOp::Inner => "|",
            BinaryOp::Outer => "^",
            BinaryOp::Add => "+",
            BinaryOp::Sub => "-",
            BinaryOp::Mul => "*",
            BinaryOp::MatMul => "@",
            BinaryOp::Div => "/",
            BinaryOp::Pow => "**",
        }
    }
}

impl Expr {
    /// Number of nodes in the tree.
    pub fn node_count(&self) -> usize {
        1 + match &self.kind {
            ExprKind::Number(_) | ExprKind::Name(_) => 0,
            ExprKind::Attribute(base, _) => base.node_count(),
            ExprKind::Call(callee, args) => {
                callee.node_count() + args.iter().map(Expr::node_count).sum::<usize>()
            }
            ExprKind::Unary(_, x) => x.node_count(),
            ExprKind::Index(base, index) => base.node_count() + index.node_count(),
            ExprKind::Binary(_, a, b) => a.node_count() + b.node_count(),
        }
    }
}

/// Prints the tree back as an expression, every operation in parentheses, so that parsing
/// the text gives the same tree.
impl fmt::Display for Expr {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.kind {
            // Rust prints the shortest text that reads back as the same f64.
            ExprKind::Number(n) => write!(f, "{n:?}"),
            ExprKind::Name(name) => f.write_str(name),
            ExprKind::Attribute(base, name) => write!(f, "{base}.{name}"),
            ExprKind::Call(callee, args) => {
                write!(f, "{callee}(")?;
                for (i, arg) in args.iter().enumerate() {
                    if i > 0 {
                        f.write_str(", ")?;
                    }
                    write!(f, "{arg}")?;
                }
                f.write_str(")")
            }
            ExprKind::Index(base, index) => write!(f, "{base}[{index}]"),
            ExprKind::Unary(op, x) => {
                let symbol = match op {
                    UnaryOp::Neg => "-",
                    UnaryOp::Plus => "+",
                    UnaryOp::Reverse => "~",
                };
                write!(f, "({symbol}{x})")
            }
            ExprKind::Binary(op, a, b) => write!(f, "({a} {} {b})", op.symbol()),
        }
    }
}
