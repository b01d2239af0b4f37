//! Evaluation of a syntax tree to a multivector. Nothing is executed: names resolve to a
//! fixed table of blades, constants and functions, and every step is counted.

use super::ast::{BinaryOp, Expr, ExprKind, UnaryOp};
use super::error::{ExprError, ExprErrorKind};
use super::{Bindings, Limits};
use cga::{CgaError, Multivector};
use glam::DVec3;

/// A value during evaluation.
// Values live briefly on the stack; boxing the multivector would allocate at every node.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug)]
enum Value {
    /// A number or multivector.
    Mv(Multivector),
    /// A bound object variable, by index into the bindings.
    Object(usize),
    /// `np`, `numpy` or `math`: only its attributes mean something.
    Module(String),
    /// A constructor or function, waiting to be called.
    Function(Function),
}

/// Built-in constructors and functions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Function {
    T,
    R,
    D,
    Up,
    Down,
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Atan2,
    Sqrt,
    Abs,
    Min,
    Max,
    Radians,
    Degrees,
    // The Euclidean dialect's matrices.
    Translation,
    RotationX,
    RotationY,
    RotationZ,
    Scaling,
    Identity,
}

const FUNCTIONS: &[(&str, Function)] = &[
    ("T", Function::T),
    ("R", Function::R),
    ("D", Function::D),
    ("up", Function::Up),
    ("down", Function::Down),
    ("sin", Function::Sin),
    ("cos", Function::Cos),
    ("tan", Function::Tan),
    ("asin", Function::Asin),
    ("arcsin", Function::Asin),
    ("acos", Function::Acos),
    ("arccos", Function::Acos),
    ("atan", Function::Atan),
    ("arctan", Function::Atan),
    ("atan2", Function::Atan2),
    ("arctan2", Function::Atan2),
    ("sqrt", Function::Sqrt),
    ("abs", Function::Abs),
    ("min", Function::Min),
    ("max", Function::Max),
    ("radians", Function::Radians),
    ("deg2rad", Function::Radians),
    ("degrees", Function::Degrees),
    ("rad2deg", Function::Degrees),
    ("translation", Function::Translation),
    ("rotation_x", Function::RotationX),
    ("rotation_y", Function::RotationY),
    ("rotation_z", Function::RotationZ),
    ("scaling", Function::Scaling),
    ("identity", Function::Identity),
];

/// Which dialect's names an expression may use.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Dialect {
    /// The CGA language (SPEC §4): blades, T, R, D, up, down.
    #[default]
    Cga,
    /// The Euclidean baseline: translation, rotation_x/y/z, scaling, `@`, indexing.
    Euclidean,
}

impl Function {
    /// Whether the function belongs to the dialect (math functions belong to both).
    fn in_dialect(self, dialect: Dialect) -> bool {
        let cga = matches!(
            self,
            Function::T | Function::R | Function::D | Function::Up | Function::Down
        );
        let euclidean = matches!(
            self,
            Function::Translation
                | Function::RotationX
                | Function::RotationY
                | Function::RotationZ
                | Function::Scaling
                | Function::Identity
        );
        match dialect {
            Dialect::Cga => !euclidean,
            Dialect::Euclidean => !cga,
        }
    }
}

/// Names a model may write that are worth a suggestion when misspelt.
const KNOWN_NAMES: &[&str] = &[
    "e1", "e2", "e3", "e4", "e5", "eo", "einf", "pi", "T", "R", "D", "up", "down", "sin", "cos",
    "tan", "asin", "acos", "atan", "atan2", "sqrt", "abs", "min", "max", "radians", "degrees",
];

impl Function {
    fn name(self) -> &'static str {
        FUNCTIONS
            .iter()
            .find(|(_, f)| *f == self)
            .map_or("?", |(n, _)| n)
    }
}

/// Evaluates expressions against bound objects, within limits.
pub struct Evaluator<'a> {
    source: &'a str,
    bindings: &'a Bindings,
    limits: &'a Limits,
    steps: usize,
    dialect: Dialect,
}

impl<'a> Evaluator<'a> {
    /// An evaluator for the expression text `source` (for error positions).
    pub fn new(source: &'a str, bindings: &'a Bindings, limits: &'a Limits) -> Self {
        Self {
            source,
            bindings,
            limits,
            steps: 0,
            dialect: Dialect::Cga,
        }
    }

    /// The same evaluator for another dialect's names.
    pub fn with_dialect(mut self, dialect: Dialect) -> Self {
        self.dialect = dialect;
        self
    }

    /// Evaluates `expr` to a multivector.
    pub fn evaluate(&mut self, expr: &Expr) -> Result<Multivector, ExprError> {
        let value = self.value(expr)?;
        self.expect_mv(value, expr)
    }

    fn error(&self, message: impl Into<String>, expr: &Expr) -> ExprError {
        ExprError::at(ExprErrorKind::Meaning, message, &expr.span, self.source)
    }

    fn value(&mut self, expr: &Expr) -> Result<Value, ExprError> {
        self.steps += 1;
        if self.steps > self.limits.max_steps {
            return Err(ExprError::at(
                ExprErrorKind::Limit,
                format!("evaluation takes more than {} steps", self.limits.max_steps),
                &expr.span,
                self.source,
            ));
        }
        match &expr.kind {
            ExprKind::Number(n) => Ok(Value::Mv(Multivector::scalar(*n))),
            ExprKind::Name(name) => self.name(name, expr),
            ExprKind::Attribute(base, name) => self.attribute(base, name, expr),
            ExprKind::Call(callee, args) => self.call(callee, args, expr),
            ExprKind::Index(base, index) => self.index(base, index, expr),
            ExprKind::Unary(op, x) => {
                let v = self.value(x)?;
                let v = self.expect_mv(v, x)?;
                Ok(Value::Mv(match op {
                    UnaryOp::Neg => -v,
                    UnaryOp::Plus => v,
                    UnaryOp::Reverse => v.reverse(),
                }))
            }
            ExprKind::Binary(op, a, b) => {
                let va = self.value(a)?;
                let va = self.expect_mv(va, a)?;
                let vb = self.value(b)?;
                let vb = self.expect_mv(vb, b)?;
                self.binary(*op, va, vb, b, expr).map(Value::Mv)
            }
        }
    }

    fn expect_mv(&self, value: Value, expr: &Expr) -> Result<Multivector, ExprError> {
        match value {
            Value::Mv(m) => {
                if m.is_finite() {
                    Ok(m)
                } else {
                    Err(self.error("the value is not a finite number (overflow or NaN)", expr))
                }
            }
            Value::Object(i) => Err(self.error(
                format!(
                    "{} is an object, not a value: use {0}.min, {0}.max, {0}.center or {0}.size",
                    self.bindings.variable(i)
                ),
                expr,
            )),
            Value::Module(m) => Err(self.error(
                format!("'{m}' is a module: use one of its names, such as {m}.pi"),
                expr,
            )),
            Value::Function(f) => Err(self.error(
                format!(
                    "{} is a function: call it, as in {}(...)",
                    f.name(),
                    f.name()
                ),
                expr,
            )),
        }
    }

    fn name(&self, name: &str, expr: &Expr) -> Result<Value, ExprError> {
        if let Some(value) = builtin_name(name, self.dialect) {
            return Ok(value);
        }
        if self.dialect == Dialect::Euclidean && builtin_name(name, Dialect::Cga).is_some() {
            return Err(self.error(
                format!("'{name}' is not available here: compose translation(dx, dy, dz), rotation_x/y/z(theta) and scaling(s) with @"),
                expr,
            ));
        }
        if let Some(index) = self.bindings.index_of(name) {
            return Ok(Value::Object(index));
        }
        if matches!(name, "np" | "numpy" | "math") {
            return Ok(Value::Module(name.to_string()));
        }
        let is_variable = name.len() > 1
            && (name.starts_with('X') || name.starts_with('x'))
            && name[1..].chars().all(|c| c.is_ascii_digit());
        if is_variable {
            let bound = self.bindings.variables().collect::<Vec<_>>().join(", ");
            let bound = if bound.is_empty() {
                "none".to_string()
            } else {
                bound
            };
            return Err(self.error(format!("unknown name '{name}' (bound: {bound})"), expr));
        }
        if name.starts_with('e') && name[1..].chars().all(|c| c.is_ascii_digit()) {
            return Err(self.error(
                format!(
                    "unknown blade '{name}': blades are e1 … e5 and products of different ones such as e12 or e123"
                ),
                expr,
            ));
        }
        let suggestion = KNOWN_NAMES
            .iter()
            .map(|k| (strsim::jaro_winkler(k, name), k))
            .filter(|(score, _)| *score > 0.8)
            .max_by(|a, b| a.0.total_cmp(&b.0))
            .map(|(_, k)| format!(" — did you mean '{k}'?"))
            .unwrap_or_default();
        Err(self.error(format!("unknown name '{name}'{suggestion}"), expr))
    }

    fn attribute(&mut self, base: &Expr, name: &str, expr: &Expr) -> Result<Value, ExprError> {
        match self.value(base)? {
            Value::Module(module) => match builtin_name(name, self.dialect) {
                Some(value @ (Value::Function(_) | Value::Mv(_))) if !name.starts_with('e') => {
                    Ok(value)
                }
                _ => Err(self.error(format!("'{module}' has no name '{name}' here"), expr)),
            },
            Value::Object(index) => {
                let b = self.bindings.object(index);
                let v = match name {
                    "min" => b.min,
                    "max" => b.max,
                    "center" | "centre" => (b.min + b.max) * 0.5,
                    "size" => b.max - b.min,
                    "front" => b.front,
                    _ => {
                        return Err(self.error(
                            format!(
                                "{} has no attribute '{name}': use .min, .max, .center, .size or .front",
                                self.bindings.variable(index)
                            ),
                            expr,
                        ))
                    }
                };
                Ok(Value::Mv(Multivector::from_vector(v)))
            }
            _ => Err(self.error(
                format!(
                    "only objects (X1, X2, …) and np/math have attributes; '.{name}' cannot apply here"
                ),
                expr,
            )),
        }
    }

    fn index(&mut self, base: &Expr, index: &Expr, expr: &Expr) -> Result<Value, ExprError> {
        if self.dialect == Dialect::Cga {
            return Err(self.error(
                "indexing is not part of the CGA language: take a coordinate with the inner product, as in (X1.max | e2)",
                expr,
            ));
        }
        let v = self.value(base)?;
        let v = self.expect_mv(v, base)?;
        let i = self.value(index)?;
        let i = self.expect_mv(i, index)?;
        let k = scalar_of(&i)
            .filter(|k| k.fract() == 0.0 && (0.0..3.0).contains(k))
            .ok_or_else(|| self.error("an index must be 0, 1 or 2 (x, y, z)", index))?;
        let mut rest = v;
        for c in 1..4 {
            rest[c] = 0.0;
        }
        if rest.max_abs() > 0.0 {
            return Err(self.error(
                "only a coordinate triple such as X1.min can be indexed",
                base,
            ));
        }
        Ok(Value::Mv(Multivector::scalar(v[k as usize + 1])))
    }

    fn binary(
        &self,
        op: BinaryOp,
        a: Multivector,
        b: Multivector,
        b_expr: &Expr,
        expr: &Expr,
    ) -> Result<Multivector, ExprError> {
        Ok(match op {
            BinaryOp::Inner => a | b,
            BinaryOp::Outer => a ^ b,
            BinaryOp::Add => a + b,
            BinaryOp::Sub => a - b,
            BinaryOp::Mul => a * b,
            BinaryOp::MatMul if self.dialect == Dialect::Cga => {
                return Err(self.error(
                    "'@' is not part of the CGA language: use * for the geometric product",
                    expr,
                ))
            }
            BinaryOp::MatMul => a * b,
            BinaryOp::Div => {
                let divisor = scalar_of(&b).ok_or_else(|| {
                    self.error(
                        format!(
                            "division by the multivector {b}: only division by a number is allowed"
                        ),
                        b_expr,
                    )
                })?;
                if divisor == 0.0 {
                    return Err(self.error("division by zero", b_expr));
                }
                a / divisor
            }
            BinaryOp::Pow => {
                let exponent = scalar_of(&b)
                    .ok_or_else(|| self.error("the exponent of ** must be a number", b_expr))?;
                if let Some(base) = scalar_of(&a) {
                    let value = base.powf(exponent);
                    if !value.is_finite() {
                        return Err(self
                            .error(format!("{base} ** {exponent} is not a finite number"), expr));
                    }
                    return Ok(Multivector::scalar(value));
                }
                if exponent.fract() != 0.0 || exponent.abs() > self.limits.max_exponent as f64 {
                    return Err(self.error(
                        format!(
                            "a multivector can only be raised to a whole number from -{0} to {0}",
                            self.limits.max_exponent
                        ),
                        b_expr,
                    ));
                }
                a.powi(exponent as i32)
                    .map_err(|e| self.error(cga_message(&e), expr))?
            }
        })
    }

    fn call(&mut self, callee: &Expr, args: &[Expr], expr: &Expr) -> Result<Value, ExprError> {
        let function = match self.value(callee)? {
            Value::Function(f) => f,
            Value::Object(i) => {
                return Err(self.error(
                    format!(
                        "{} is an object and cannot be called",
                        self.bindings.variable(i)
                    ),
                    callee,
                ))
            }
            _ => {
                return Err(self.error(
                    "only T, R, D, up, down and math functions can be called",
                    callee,
                ))
            }
        };
        let mut values = Vec::with_capacity(args.len());
        for arg in args {
            let v = self.value(arg)?;
            values.push(self.expect_mv(v, arg)?);
        }
        let result = match function {
            Function::Min
            | Function::Max
            | Function::Atan2
            | Function::Abs
            | Function::Sin
            | Function::Cos
            | Function::Tan
            | Function::Asin
            | Function::Acos
            | Function::Atan
            | Function::Sqrt
            | Function::Radians
            | Function::Degrees => self.math(function, &values, args, expr)?,
            _ => self.versor(function, &values, args, expr)?,
        };
        Ok(Value::Mv(result))
    }

    /// A call of a function that makes a versor or a point: T, R, D, up, down, and the
    /// Euclidean baseline's translation, rotations, scaling and identity.
    fn versor(
        &mut self,
        function: Function,
        values: &[Multivector],
        args: &[Expr],
        expr: &Expr,
    ) -> Result<Multivector, ExprError> {
        Ok(match function {
            Function::T => self.translator(values, args, expr)?,
            Function::R => self.rotor(values, args, expr)?,
            Function::D | Function::Scaling => {
                self.arity(function, values, 1, "a scale factor", expr)?;
                let s = self.number(function, &values[0], &args[0])?;
                Multivector::dilator(s).map_err(|e| {
                    let message = cga_message(&e);
                    let message = if function == Function::Scaling {
                        message.replace("D(", "scaling(")
                    } else {
                        message
                    };
                    self.error(message, expr)
                })?
            }
            Function::Up => {
                self.arity(function, values, 1, "a Euclidean vector", expr)?;
                Multivector::up(self.euclidean(function, &values[0], &args[0])?)
            }
            Function::Down => {
                self.arity(function, values, 1, "a conformal point", expr)?;
                let x = values[0]
                    .down()
                    .map_err(|e| self.error(cga_message(&e), &args[0]))?;
                Multivector::from_vector(x)
            }
            Function::Translation => {
                self.arity(function, values, 3, "dx, dy, dz", expr)?;
                let mut t = [0.0; 3];
                for (k, (v, a)) in values.iter().zip(args).enumerate() {
                    t[k] = self.number(function, v, a)?;
                }
                Multivector::translator(DVec3::from(t))
            }
            Function::RotationX | Function::RotationY | Function::RotationZ => {
                self.arity(function, values, 1, "an angle in radians", expr)?;
                let angle = self.number(function, &values[0], &args[0])?;
                // Right-hand rule about each axis: y → z about x, z → x about y, x → y about z.
                let (u, v) = match function {
                    Function::RotationX => (Multivector::e2(), Multivector::e3()),
                    Function::RotationY => (Multivector::e3(), Multivector::e1()),
                    _ => (Multivector::e1(), Multivector::e2()),
                };
                Multivector::rotor(angle, &u, &v).map_err(|e| self.error(cga_message(&e), expr))?
            }
            _ => {
                self.arity(function, values, 0, "nothing", expr)?;
                Multivector::ONE
            }
        })
    }

    /// A call of a math function: min, max, atan2, abs and the functions of one number.
    fn math(
        &mut self,
        function: Function,
        values: &[Multivector],
        args: &[Expr],
        expr: &Expr,
    ) -> Result<Multivector, ExprError> {
        Ok(match function {
            Function::Min | Function::Max => {
                if values.len() < 2 {
                    return Err(self.error(
                        format!("{} needs at least two numbers", function.name()),
                        expr,
                    ));
                }
                let mut best = self.number(function, &values[0], &args[0])?;
                for (v, a) in values.iter().zip(args).skip(1) {
                    let x = self.number(function, v, a)?;
                    best = if function == Function::Min {
                        best.min(x)
                    } else {
                        best.max(x)
                    };
                }
                Multivector::scalar(best)
            }
            Function::Atan2 => {
                self.arity(function, values, 2, "two numbers: y, x", expr)?;
                let y = self.number(function, &values[0], &args[0])?;
                let x = self.number(function, &values[1], &args[1])?;
                Multivector::scalar(y.atan2(x))
            }
            Function::Abs => {
                self.arity(function, values, 1, "one value", expr)?;
                match scalar_of(&values[0]) {
                    Some(x) => Multivector::scalar(x.abs()),
                    None => Multivector::scalar(values[0].norm()),
                }
            }
            _ => {
                self.arity(function, values, 1, "one number", expr)?;
                let x = self.number(function, &values[0], &args[0])?;
                let (value, domain) = match function {
                    Function::Sin => (x.sin(), ""),
                    Function::Cos => (x.cos(), ""),
                    Function::Tan => (x.tan(), ""),
                    Function::Asin => (x.asin(), " in [-1, 1]"),
                    Function::Acos => (x.acos(), " in [-1, 1]"),
                    Function::Atan => (x.atan(), ""),
                    Function::Sqrt => (x.sqrt(), " ≥ 0"),
                    Function::Radians => (x.to_radians(), ""),
                    _ => (x.to_degrees(), ""),
                };
                if !value.is_finite() {
                    return Err(self.error(
                        format!(
                            "{}({x}) is undefined: it needs a number{domain}",
                            function.name()
                        ),
                        expr,
                    ));
                }
                Multivector::scalar(value)
            }
        })
    }

    fn arity(
        &self,
        function: Function,
        values: &[Multivector],
        count: usize,
        what: &str,
        expr: &Expr,
    ) -> Result<(), ExprError> {
        if values.len() == count {
            return Ok(());
        }
        let plural = if count == 1 { "argument" } else { "arguments" };
        let count_word = ["no", "one", "two", "three"]
            .get(count)
            .copied()
            .unwrap_or("several");
        Err(self.error(
            format!(
                "{} needs {count_word} {plural}: {what} (got {})",
                function.name(),
                values.len()
            ),
            expr,
        ))
    }

    fn number(
        &self,
        function: Function,
        value: &Multivector,
        expr: &Expr,
    ) -> Result<f64, ExprError> {
        scalar_of(value).ok_or_else(|| {
            self.error(
                format!(
                    "{} needs a number here, got the multivector {value}",
                    function.name()
                ),
                expr,
            )
        })
    }

    fn euclidean(
        &self,
        function: Function,
        value: &Multivector,
        expr: &Expr,
    ) -> Result<DVec3, ExprError> {
        let v = value.euclidean_vector();
        let mut rest = *value;
        for i in 1..4 {
            rest[i] = 0.0;
        }
        let tolerance = 1e-9 * value.max_abs().max(1.0);
        if rest.max_abs() <= tolerance {
            return Ok(v);
        }
        let hint = if let Some(x) = scalar_of(value) {
            format!(
                "{0} needs a vector, not the number {x}: write a direction, as in {0}({x} * e1)",
                function.name()
            )
        } else {
            format!(
                "{} needs a Euclidean vector (a combination of e1, e2, e3), got {value}",
                function.name()
            )
        };
        Err(self.error(hint, expr))
    }

    fn translator(
        &self,
        values: &[Multivector],
        args: &[Expr],
        expr: &Expr,
    ) -> Result<Multivector, ExprError> {
        let t = match values.len() {
            1 => self.euclidean(Function::T, &values[0], &args[0])?,
            // An extension for models that write T(x, y, z).
            3 => {
                let mut c = [0.0; 3];
                for (i, (v, a)) in values.iter().zip(args).enumerate() {
                    c[i] = self.number(Function::T, v, a)?;
                }
                DVec3::from(c)
            }
            n => {
                return Err(self.error(
                    format!("T needs one argument: a translation vector such as 2 * e1 (got {n})"),
                    expr,
                ))
            }
        };
        Ok(Multivector::translator(t))
    }

    fn rotor(
        &self,
        values: &[Multivector],
        args: &[Expr],
        expr: &Expr,
    ) -> Result<Multivector, ExprError> {
        let (u, v) = match values.len() {
            3 => (values[1], values[2]),
            2 => return self.rotor_in_plane(values, args, expr),
            n => {
                return Err(self.error(
                    format!("R needs three arguments: angle, u, v (got {n}); for example R(pi/2, e3, e1) turns +90° about +Y"),
                    expr,
                ))
            }
        };
        let angle = scalar_of(&values[0]).ok_or_else(|| {
            self.error(
                format!(
                    "the angle of R must be a number in radians, got the multivector {}",
                    values[0]
                ),
                &args[0],
            )
        })?;
        for (value, arg, which) in [(&u, &args[1], "u"), (&v, &args[2], "v")] {
            if value.grades_present(1e-12) & !0b10 != 0 {
                return Err(self.error(
                    format!("{which} of R(angle, u, v) must be a vector such as e1, got {value}"),
                    arg,
                ));
            }
        }
        Multivector::rotor(angle, &u, &v).map_err(|e| self.error(cga_message(&e), expr))
    }
}

impl Evaluator<'_> {
    /// `R(B, angle)` or `R(angle, B)`: a rotation by `angle` in the plane of the Euclidean
    /// bivector `B`, in the sense from `u` to `v` where `B = u ∧ v` — `R(e12, a)` is
    /// `R(a, e1, e2)`, `R(e31, a)` is `R(a, e3, e1)`.
    fn rotor_in_plane(
        &self,
        values: &[Multivector],
        args: &[Expr],
        expr: &Expr,
    ) -> Result<Multivector, ExprError> {
        let (plane, angle, plane_arg) = match (scalar_of(&values[0]), scalar_of(&values[1])) {
            (None, Some(angle)) => (values[0], angle, &args[0]),
            (Some(angle), None) => (values[1], angle, &args[1]),
            _ => {
                return Err(self.error(
                    "R with two arguments takes a plane and an angle, as R(e31, pi/2); or write R(angle, u, v)",
                    expr,
                ))
            }
        };
        let at = |name: &str| {
            cga::BLADE_NAMES
                .iter()
                .position(|n| *n == name)
                .map_or(0.0, |i| plane[i])
        };
        let mut rest = plane;
        for name in ["e12", "e13", "e23"] {
            if let Some(i) = cga::BLADE_NAMES.iter().position(|n| *n == name) {
                rest[i] = 0.0;
            }
        }
        // The plane's normal: e23 ↔ e1, e31 ↔ e2, e12 ↔ e3.
        let normal = DVec3::new(at("e23"), -at("e13"), at("e12"));
        if rest.max_abs() > 1e-12 || normal.length() < 1e-12 {
            return Err(self.error(
                format!("the plane of R must be a Euclidean bivector such as e12, e31 or e23, got {plane}"),
                plane_arg,
            ));
        }
        let n = normal.normalize();
        let u = n.any_orthonormal_vector();
        let v = n.cross(u);
        Multivector::rotor(
            angle,
            &Multivector::from_vector(u),
            &Multivector::from_vector(v),
        )
        .map_err(|e| self.error(cga_message(&e), expr))
    }
}

/// The value of a name from the fixed table of a dialect: blades, constants, functions.
fn builtin_name(name: &str, dialect: Dialect) -> Option<Value> {
    if let Some((_, f)) = FUNCTIONS
        .iter()
        .find(|(n, f)| *n == name && f.in_dialect(dialect))
    {
        return Some(Value::Function(*f));
    }
    if name == "pi" {
        return Some(Value::Mv(Multivector::scalar(std::f64::consts::PI)));
    }
    if dialect == Dialect::Euclidean {
        return None;
    }
    let mv = match name {
        "eo" | "e0" | "no" => Multivector::eo(),
        "einf" | "ninf" => Multivector::einf(),
        _ => blade(name)?,
    };
    Some(Value::Mv(mv))
}

/// A blade name `e` followed by distinct digits 1–5 in any order: `e31` is `-e13`.
fn blade(name: &str) -> Option<Multivector> {
    let digits = name.strip_prefix('e')?;
    if digits.is_empty() || digits.len() > 5 {
        return None;
    }
    let mut result = Multivector::ONE;
    let mut seen = 0u8;
    for c in digits.chars() {
        let d = c.to_digit(10).filter(|d| (1..=5).contains(d))? as usize;
        if seen & (1 << d) != 0 {
            return None;
        }
        seen |= 1 << d;
        result = result * Multivector::basis_blade(d);
    }
    Some(result)
}

/// The number a multivector is, if it has no part but the scalar.
fn scalar_of(m: &Multivector) -> Option<f64> {
    let mut rest = *m;
    rest[0] = 0.0;
    (rest.max_abs() == 0.0).then(|| m.scalar_part())
}

/// An algebra error in words for the expression's author.
pub(super) fn cga_message(e: &CgaError) -> String {
    e.to_string()
}
