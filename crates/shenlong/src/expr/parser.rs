//! A Pratt parser with Python's precedence (as the `clifford` library uses it):
//! `|` lowest, then `^`, then `+ -`, then `* /`, then unary `- + ~`, then `**` (right
//! associative, and binding tighter than a unary operator on its left: `-x**2` is
//! `-(x**2)`).

use super::ast::{BinaryOp, Expr, ExprKind, UnaryOp};
use super::error::{ExprError, ExprErrorKind};
use super::lexer::{tokenize, Token, TokenKind};
use super::Limits;

/// Parses one expression.
pub fn parse(source: &str, limits: &Limits) -> Result<Expr, ExprError> {
    if source.len() > limits.max_length {
        return Err(ExprError::whole(
            ExprErrorKind::Limit,
            format!(
                "the expression is {} characters long; the limit is {}",
                source.len(),
                limits.max_length
            ),
        ));
    }
    if source.trim().is_empty() {
        return Err(ExprError::whole(
            ExprErrorKind::Syntax,
            "the expression is empty: write a transformation such as T(1 * e1)",
        ));
    }
    let tokens = tokenize(source)?;
    let mut parser = Parser {
        source,
        tokens,
        position: 0,
        depth: 0,
        nodes: 0,
        limits,
    };
    let expr = parser.expression(0)?;
    let token = parser.peek();
    if token.kind != TokenKind::End {
        let hint = match token.kind {
            TokenKind::RParen => ": there is one ')' too many".to_string(),
            _ => format!(": an operator is missing before {}", token.kind.describe()),
        };
        return Err(parser.error_at_current(format!("unexpected {}{hint}", token.kind.describe())));
    }
    Ok(expr)
}

struct Parser<'a> {
    source: &'a str,
    tokens: Vec<Token>,
    position: usize,
    depth: usize,
    nodes: usize,
    limits: &'a Limits,
}

/// Binding power of an infix operator (left, right), or None if the token is not one.
fn infix_power(kind: &TokenKind) -> Option<(u8, u8, BinaryOp)> {
    Some(match kind {
        TokenKind::Pipe => (1, 2, BinaryOp::Inner),
        TokenKind::Caret => (3, 4, BinaryOp::Outer),
        TokenKind::Plus => (5, 6, BinaryOp::Add),
        TokenKind::Minus => (5, 6, BinaryOp::Sub),
        TokenKind::Star => (7, 8, BinaryOp::Mul),
        TokenKind::At => (7, 8, BinaryOp::MatMul),
        TokenKind::Slash => (7, 8, BinaryOp::Div),
        // Right associative; the right side is a unary expression (`2 ** -1`).
        TokenKind::StarStar => (11, 9, BinaryOp::Pow),
        _ => return None,
    })
}

/// Binding power of the operand of a prefix operator: above `* /`, below `**`.
const PREFIX_POWER: u8 = 9;

impl Parser<'_> {
    fn peek(&self) -> &Token {
        &self.tokens[self.position]
    }

    fn advance(&mut self) -> Token {
        let token = self.tokens[self.position].clone();
        if token.kind != TokenKind::End {
            self.position += 1;
        }
        token
    }

    fn error_at_current(&self, message: String) -> ExprError {
        ExprError::at(
            ExprErrorKind::Syntax,
            message,
            &self.peek().span,
            self.source,
        )
    }

    fn node(&mut self, kind: ExprKind, span: std::ops::Range<usize>) -> Result<Expr, ExprError> {
        self.nodes += 1;
        if self.nodes > self.limits.max_nodes {
            return Err(ExprError::at(
                ExprErrorKind::Limit,
                format!(
                    "the expression is too large (more than {} parts); write a shorter one",
                    self.limits.max_nodes
                ),
                &span,
                self.source,
            ));
        }
        Ok(Expr { kind, span })
    }

    fn enter(&mut self) -> Result<(), ExprError> {
        self.depth += 1;
        if self.depth > self.limits.max_depth {
            return Err(self.error_at_current(format!(
                "the expression nests more than {} levels deep",
                self.limits.max_depth
            )));
        }
        Ok(())
    }

    fn expression(&mut self, min_power: u8) -> Result<Expr, ExprError> {
        self.enter()?;
        let mut left = self.prefix()?;
        while let Some((left_power, right_power, op)) = infix_power(&self.peek().kind) {
            if left_power < min_power {
                break;
            }
            self.advance();
            let right = self.expression(right_power)?;
            let span = left.span.start..right.span.end;
            left = self.node(ExprKind::Binary(op, Box::new(left), Box::new(right)), span)?;
        }
        self.depth -= 1;
        Ok(left)
    }

    fn prefix(&mut self) -> Result<Expr, ExprError> {
        let token = self.peek().clone();
        let op = match token.kind {
            TokenKind::Minus => Some(UnaryOp::Neg),
            TokenKind::Plus => Some(UnaryOp::Plus),
            TokenKind::Tilde => Some(UnaryOp::Reverse),
            _ => None,
        };
        if let Some(op) = op {
            self.advance();
            let operand = self.expression(PREFIX_POWER)?;
            let span = token.span.start..operand.span.end;
            return self.node(ExprKind::Unary(op, Box::new(operand)), span);
        }
        let mut expr = self.primary()?;
        // Postfix: calls and attributes.
        loop {
            match self.peek().kind {
                TokenKind::LParen => {
                    self.enter()?;
                    self.advance();
                    let arguments = self.arguments()?;
                    let close = self.expect_close_paren()?;
                    let span = expr.span.start..close;
                    expr = self.node(ExprKind::Call(Box::new(expr), arguments), span)?;
                    self.depth -= 1;
                }
                TokenKind::LBracket => {
                    self.enter()?;
                    self.advance();
                    let index = self.expression(0)?;
                    let close = self.peek().clone();
                    if close.kind != TokenKind::RBracket {
                        return Err(ExprError::at(
                            ExprErrorKind::Syntax,
                            format!("expected ']' but found {}", close.kind.describe()),
                            &close.span,
                            self.source,
                        ));
                    }
                    self.advance();
                    let span = expr.span.start..close.span.end;
                    expr = self.node(ExprKind::Index(Box::new(expr), Box::new(index)), span)?;
                    self.depth -= 1;
                }
                TokenKind::Dot => {
                    self.advance();
                    let name_token = self.advance();
                    let TokenKind::Name(name) = name_token.kind else {
                        return Err(ExprError::at(
                            ExprErrorKind::Syntax,
                            format!(
                                "expected a name after '.', found {}",
                                name_token.kind.describe()
                            ),
                            &name_token.span,
                            self.source,
                        ));
                    };
                    let span = expr.span.start..name_token.span.end;
                    expr = self.node(ExprKind::Attribute(Box::new(expr), name), span)?;
                }
                _ => return Ok(expr),
            }
        }
    }

    fn arguments(&mut self) -> Result<Vec<Expr>, ExprError> {
        let mut arguments = Vec::new();
        if self.peek().kind == TokenKind::RParen {
            return Ok(arguments);
        }
        loop {
            arguments.push(self.expression(0)?);
            if self.peek().kind != TokenKind::Comma {
                return Ok(arguments);
            }
            self.advance();
            // Python allows a trailing comma.
            if self.peek().kind == TokenKind::RParen {
                return Ok(arguments);
            }
        }
    }

    fn expect_close_paren(&mut self) -> Result<usize, ExprError> {
        let token = self.peek().clone();
        if token.kind == TokenKind::RParen {
            self.advance();
            return Ok(token.span.end);
        }
        Err(ExprError::at(
            ExprErrorKind::Syntax,
            format!("expected ')' but found {}", token.kind.describe()),
            &token.span,
            self.source,
        ))
    }

    fn primary(&mut self) -> Result<Expr, ExprError> {
        let token = self.advance();
        match token.kind {
            TokenKind::Number(value) => self.node(ExprKind::Number(value), token.span),
            TokenKind::Name(name) => self.node(ExprKind::Name(name), token.span),
            TokenKind::LParen => {
                self.enter()?;
                let inner = self.expression(0)?;
                let close = self.expect_close_paren()?;
                self.depth -= 1;
                // Parentheses only group: the inner node, its span widened to them.
                Ok(Expr {
                    kind: inner.kind,
                    span: token.span.start..close,
                })
            }
            other => Err(ExprError::at(
                ExprErrorKind::Syntax,
                format!("expected a value but found {}", other.describe()),
                &token.span,
                self.source,
            )),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(s: &str) -> String {
        parse(s, &Limits::default()).unwrap().to_string()
    }

    fn err(s: &str) -> String {
        parse(s, &Limits::default()).unwrap_err().to_string()
    }

    #[test]
    fn precedence_follows_python() {
        assert_eq!(
            p("a | b ^ c + d * e ** f"),
            "(a | (b ^ (c + (d * (e ** f)))))"
        );
        assert_eq!(p("a * b + c | d"), "(((a * b) + c) | d)");
        assert_eq!(p("a - b - c"), "((a - b) - c)");
        assert_eq!(p("a / b * c"), "((a / b) * c)");
        assert_eq!(p("a ** b ** c"), "(a ** (b ** c))");
        assert_eq!(p("-a ** 2"), "(-(a ** 2.0))");
        assert_eq!(p("-a * b"), "((-a) * b)");
        assert_eq!(p("2 ** -1"), "(2.0 ** (-1.0))");
        assert_eq!(p("~a * b"), "((~a) * b)");
        assert_eq!(p("a ^ b | c ^ d"), "((a ^ b) | (c ^ d))");
    }

    #[test]
    fn calls_and_attributes() {
        assert_eq!(
            p("T(((X2.max | e2) - (X1.min | e2)) * e2)"),
            "T((((X2.max | e2) - (X1.min | e2)) * e2))"
        );
        assert_eq!(p("R(np.pi/2, e1, e3)"), "R((np.pi / 2.0), e1, e3)");
        assert_eq!(p("f()"), "f()");
        assert_eq!(p("max(1, 2,)"), "max(1.0, 2.0)");
    }

    #[test]
    fn syntax_errors_say_what_and_where() {
        assert_eq!(
            err("T(e1 * 2"),
            "expected ')' but found the end of the expression at column 9"
        );
        assert_eq!(
            err("T(e1))"),
            "unexpected ')': there is one ')' too many at column 6"
        );
        assert_eq!(
            err("e1 e2"),
            "unexpected name 'e2': an operator is missing before name 'e2' at column 4"
        );
        assert_eq!(err("1 + * 2"), "expected a value but found '*' at column 5");
        assert_eq!(
            err("X1."),
            "expected a name after '.', found the end of the expression at column 4"
        );
        assert!(err("  ").contains("empty"));
    }

    #[test]
    fn limits_fail_fast() {
        assert!(err(&"T(".repeat(5000)).contains("characters long"));
        assert!(err(&"T(".repeat(1000)).contains("nests more than"));
        let long = "1+".repeat(10_000_000 / 2);
        assert!(err(&long).contains("characters long"));
        let minus = "-".repeat(1000) + "1";
        assert!(err(&minus).contains("nests more than"));
        let wide = vec!["e1"; 1100].join("+");
        assert!(err(&wide).contains("too large"));
    }
}
