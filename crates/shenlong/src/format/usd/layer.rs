//! Shenlong's own reader of a self-contained `.usda` layer: the layer's prims, their
//! types, kinds, activity and the attributes the walk needs ([`super::xform::wanted`]),
//! read in one pass over its tokens ([`super::lex`]).
//!
//! It reads only layers that need no composition: one layer of `def`s, with no
//! sublayers, references, payloads, inherits, specializes, variants, `over`s or
//! `class`es. For those, a stage is exactly its layer, and reading it costs about what
//! lexing its text costs (no composition engine). It runs in the reading child process as
//! the composing reader does ([`super::sandbox`]): its memory grows with the prims. Anything else — and
//! anything this reader does not know — it leaves to the composing reader
//! ([`Parsed::Compose`]), which reads it as before. Nothing here recurses: prims and
//! values nest on explicit stacks, bounded in depth.

use super::super::FormatError;
use super::lex::{line_of, Lexer, Token};
use super::xform::{self, Attr};

/// One prim of a layer.
#[derive(Debug)]
pub(super) struct LayerPrim {
    /// Its path (`/World/Chair`).
    pub path: String,
    /// Its type (`Xform`, `Mesh`; empty when untyped).
    pub type_name: String,
    /// Its children, in the layer's order.
    pub children: Vec<usize>,
    /// Its `kind` metadata.
    pub kind: Option<String>,
    /// Whether it is active (`active = false` makes it and its subtree absent).
    pub active: bool,
    /// The attributes the walk reads, with their default values.
    pub attrs: Vec<(String, Attr)>,
}

/// A layer read whole: its stage metadata and prims (parents before children).
#[derive(Debug, Default)]
pub(super) struct Layer {
    /// `defaultPrim`.
    pub default_prim: Option<String>,
    /// `upAxis`.
    pub up_axis: Option<String>,
    /// `metersPerUnit`, when authored as a number.
    pub meters_per_unit: Option<f64>,
    /// The prims, in the order the layer defines them.
    pub prims: Vec<LayerPrim>,
    /// The root prims.
    pub roots: Vec<usize>,
}

/// What reading a layer found.
#[derive(Debug)]
pub(super) enum Parsed {
    /// A self-contained layer: the stage it opens is this.
    Layer(Layer),
    /// A layer that needs composition, or holds what this reader does not read.
    Compose,
}

/// A layer this reader leaves to the composing reader.
struct Stop;

type Step<T> = Result<T, Stop>;

/// The deepest nesting of prims, and of brackets inside one value.
const MAX_DEPTH: usize = super::super::MAX_JSON_DEPTH;

/// Prim metadata that composes other specs: a layer holding any is left to composition.
const ARCS: [&str; 8] = [
    "references",
    "payload",
    "inherits",
    "specializes",
    "variantSets",
    "variants",
    "subLayers",
    "relocates",
];

/// List-edit words before a metadata key or a relationship.
const LIST_OPS: [&str; 5] = ["prepend", "append", "add", "delete", "reorder"];

/// Property qualifiers before a type.
const QUALIFIERS: [&str; 4] = ["custom", "uniform", "varying", "config"];

struct Parser<'a> {
    lexer: Lexer<'a>,
    peeked: Option<Token>,
    layer: Layer,
    max_prims: usize,
}

impl Parser<'_> {
    /// The next token that is not a line end.
    fn next(&mut self) -> Step<Option<Token>> {
        if let Some(t) = self.peeked.take() {
            return Ok(Some(t));
        }
        loop {
            match self.lexer.next().map_err(|_| Stop)? {
                Some((_, Token::Newline)) => {}
                other => return Ok(other.map(|(_, t)| t)),
            }
        }
    }

    fn peek(&mut self) -> Step<Option<&Token>> {
        if self.peeked.is_none() {
            self.peeked = self.next()?;
        }
        Ok(self.peeked.as_ref())
    }

    fn word(&mut self) -> Step<String> {
        match self.next()? {
            Some(Token::Word(w)) => Ok(w),
            _ => Err(Stop),
        }
    }

    fn expect(&mut self, token: &Token) -> Step<()> {
        if self.next()?.as_ref() == Some(token) {
            Ok(())
        } else {
            Err(Stop)
        }
    }

    /// Whether the next token is `token`, taking it if so.
    fn take(&mut self, token: &Token) -> Step<bool> {
        if self.peek()? == Some(token) {
            self.peeked = None;
            Ok(true)
        } else {
            Ok(false)
        }
    }

    /// One value: a word, a string, an asset or prim path, or a bracketed group read to its
    /// matching close. Its tokens when `keep`, else nothing.
    fn value(&mut self, keep: bool) -> Step<Vec<Token>> {
        let mut out = Vec::new();
        let mut depth = 0usize;
        loop {
            let token = self.next()?.ok_or(Stop)?;
            match token {
                Token::Open(_) => depth += 1,
                Token::Close(_) if depth == 0 => return Err(Stop),
                Token::Close(_) => depth -= 1,
                _ => {}
            }
            if depth > MAX_DEPTH {
                return Err(Stop);
            }
            if keep {
                out.push(token);
            }
            if depth == 0 {
                return Ok(out);
            }
        }
    }

    /// A parenthesised metadata block, its `(` taken: calls `entry` with each key and its
    /// value's tokens (kept when `keep(key)`); doc strings are passed over.
    fn metadata(
        &mut self,
        keep: impl Fn(&str) -> bool,
        mut entry: impl FnMut(&mut Self, &str, Vec<Token>) -> Step<()>,
    ) -> Step<()> {
        loop {
            match self.next()?.ok_or(Stop)? {
                Token::Close(b')') => return Ok(()),
                Token::Str(_) => {}
                Token::Word(mut key) => {
                    if LIST_OPS.contains(&key.as_str()) {
                        key = self.word()?;
                    }
                    if ARCS.contains(&key.as_str()) {
                        return Err(Stop);
                    }
                    self.expect(&Token::Punct(b'='))?;
                    let tokens = self.value(keep(&key))?;
                    entry(self, &key, tokens)?;
                }
                _ => return Err(Stop),
            }
        }
    }

    /// The layer's metadata, its `(` taken.
    fn layer_metadata(&mut self) -> Step<()> {
        let keep = |k: &str| matches!(k, "defaultPrim" | "upAxis" | "metersPerUnit");
        self.metadata(keep, |p, key, tokens| {
            match (key, tokens.as_slice()) {
                ("defaultPrim", [Token::Str(s)]) => p.layer.default_prim = Some(s.clone()),
                ("upAxis", [Token::Str(s)]) => p.layer.up_axis = Some(s.clone()),
                ("metersPerUnit", [Token::Word(w)]) => {
                    p.layer.meters_per_unit = Some(w.parse().map_err(|_| Stop)?);
                }
                ("defaultPrim" | "upAxis" | "metersPerUnit", _) => return Err(Stop),
                _ => {}
            }
            Ok(())
        })
    }

    /// A prim's header after `def`, through its `{`: the new prim's index.
    fn prim_header(&mut self, parent: Option<usize>) -> Step<usize> {
        let (type_name, name) = match self.next()? {
            Some(Token::Word(t)) => match self.next()? {
                Some(Token::Str(n)) => (t, n),
                _ => return Err(Stop),
            },
            Some(Token::Str(n)) => (String::new(), n),
            _ => return Err(Stop),
        };
        if name.is_empty() || !name.chars().all(|c| c.is_alphanumeric() || c == '_') {
            return Err(Stop);
        }
        let mut kind = None;
        let mut active = true;
        if self.take(&Token::Open(b'('))? {
            let keep = |k: &str| matches!(k, "kind" | "active");
            self.metadata(keep, |_, key, tokens| {
                match (key, tokens.as_slice()) {
                    ("kind", [Token::Str(s)]) => kind = Some(s.clone()),
                    ("active", [Token::Word(w)]) => active = !matches!(w.as_str(), "false" | "0"),
                    ("kind" | "active", _) => return Err(Stop),
                    _ => {}
                }
                Ok(())
            })?;
        }
        self.expect(&Token::Open(b'{'))?;
        let path = match parent {
            Some(p) => format!("{}/{name}", self.layer.prims[p].path),
            None => format!("/{name}"),
        };
        let index = self.layer.prims.len();
        self.layer.prims.push(LayerPrim {
            path,
            type_name,
            children: Vec::new(),
            kind,
            active,
            attrs: Vec::new(),
        });
        match parent {
            Some(p) => self.layer.prims[p].children.push(index),
            None => self.layer.roots.push(index),
        }
        Ok(index)
    }

    /// A property statement of `prim`, its first word taken: an attribute or a
    /// relationship, with its value and metadata.
    fn property(&mut self, prim: usize, first: String) -> Step<()> {
        let mut word = first;
        if LIST_OPS.contains(&word.as_str()) {
            word = self.word()?;
        }
        if word == "rel" || word == "nameChildren" || word == "properties" {
            if word == "rel" {
                self.word()?;
            }
            return self.rest_of_statement(false).map(|_| ());
        }
        while QUALIFIERS.contains(&word.as_str()) {
            word = self.word()?;
        }
        let type_name = word;
        let array = self.take(&Token::Open(b'['))?;
        if array {
            self.expect(&Token::Close(b']'))?;
        }
        let name = self.word()?;
        if let Some((base, _)) = name.split_once('.') {
            // Time samples or a spline: which value is the default is composition's call.
            if xform::wanted(base) && !name.ends_with(".connect") {
                return Err(Stop);
            }
        }
        let keep = xform::wanted(&name);
        if let Some(tokens) = self.rest_of_statement(keep)? {
            if let Some(attr) = typed(&type_name, array, &tokens) {
                self.layer.prims[prim].attrs.push((name, attr));
            }
        }
        Ok(())
    }

    /// What follows a property's name: `= value` (its tokens when `keep`) and a metadata
    /// block, each optional.
    fn rest_of_statement(&mut self, keep: bool) -> Step<Option<Vec<Token>>> {
        let value = if self.take(&Token::Punct(b'='))? {
            Some(self.value(keep)?)
        } else {
            None
        };
        if self.take(&Token::Open(b'('))? {
            self.metadata(|_| false, |_, _, _| Ok(()))?;
        }
        Ok(value.filter(|_| keep))
    }

    /// The layer's prims, on an explicit stack of the prims open.
    fn prims(&mut self) -> Result<Step<()>, FormatError> {
        let mut open: Vec<usize> = Vec::new();
        loop {
            let token = match self.next() {
                Ok(t) => t,
                Err(stop) => return Ok(Err(stop)),
            };
            let step = match (token, open.last().copied()) {
                (None, None) => return Ok(Ok(())),
                (Some(Token::Close(b'}')), Some(prim)) => {
                    self.layer.prims[prim].attrs.shrink_to_fit();
                    open.pop();
                    Ok(())
                }
                (Some(Token::Word(w)), parent) if w == "def" => {
                    self.prim_header(parent).map(|index| open.push(index))
                }
                (Some(Token::Word(w)), Some(prim))
                    if !matches!(w.as_str(), "over" | "class" | "variantSet") =>
                {
                    self.property(prim, w)
                }
                _ => Err(Stop),
            };
            if step.is_err() {
                return Ok(step);
            }
            if open.len() > MAX_DEPTH {
                return Err(FormatError::too_large(format!(
                    "nesting deeper than {MAX_DEPTH} levels at line {}",
                    line_of(self.lexer.text, self.lexer.pos)
                )));
            }
            if self.layer.prims.len() > self.max_prims {
                return Err(FormatError::too_large(format!(
                    "more than {} prims",
                    self.max_prims
                )));
            }
        }
    }
}

/// A layer's text read, when it needs no composition ([`Parsed`]).
///
/// # Errors
/// Prims nested deeper than [`MAX_DEPTH`] or more than `max_prims` of them.
pub(super) fn read(text: &str, max_prims: usize) -> Result<Parsed, FormatError> {
    if !text.starts_with("#usda ") {
        return Ok(Parsed::Compose);
    }
    let mut parser = Parser {
        lexer: Lexer {
            text: text.as_bytes(),
            pos: 0,
        },
        peeked: None,
        layer: Layer::default(),
        max_prims,
    };
    let metadata = match parser.take(&Token::Open(b'(')) {
        Ok(true) => parser.layer_metadata(),
        Ok(false) => Ok(()),
        Err(stop) => Err(stop),
    };
    if metadata.is_err() || parser.prims()?.is_err() {
        return Ok(Parsed::Compose);
    }
    Ok(Parsed::Layer(parser.layer))
}

/// The numbers of a value's words, rounded to `f32` for the single- and half-precision
/// types; `None` if a word is no number.
fn numbers(tokens: &[Token], single: bool) -> Option<Vec<f64>> {
    tokens
        .iter()
        .filter_map(|t| match t {
            Token::Word(w) => {
                Some(
                    w.parse::<f64>()
                        .ok()
                        .map(|x| if single { f64::from(x as f32) } else { x }),
                )
            }
            Token::Open(_) | Token::Close(_) | Token::Punct(b',') => None,
            _ => Some(None),
        })
        .collect()
}

/// A value's tokens as an attribute of `type_name` (an array when `array`): the kinds the
/// walk reads, `None` for any other.
fn typed(type_name: &str, array: bool, tokens: &[Token]) -> Option<Attr> {
    let single = type_name.starts_with("float")
        || type_name.starts_with("half")
        || type_name.ends_with('f')
        || type_name.ends_with('h');
    let vector = matches!(
        type_name.trim_end_matches(['d', 'f', 'h']),
        "double3" | "float3" | "half3" | "point3" | "vector3" | "normal3" | "color3"
    );
    let texts = || -> Option<Vec<String>> {
        tokens
            .iter()
            .filter_map(|t| match t {
                Token::Str(s) => Some(Some(s.clone())),
                Token::Open(_) | Token::Close(_) | Token::Punct(b',') => None,
                _ => Some(None),
            })
            .collect()
    };
    match (type_name, array) {
        ("token" | "string", false) => match tokens {
            [Token::Str(s)] => Some(Attr::Text(s.clone())),
            _ => None,
        },
        ("token" | "string", true) => texts().map(Attr::Texts),
        ("int" | "int64" | "uint", true) => numbers(tokens, false)?
            .into_iter()
            .map(|x| (x.fract() == 0.0 && x.abs() < 9.0e15).then_some(x as i64))
            .collect::<Option<Vec<_>>>()
            .map(Attr::Ints),
        (_, true) if vector => {
            let n = numbers(tokens, single)?;
            (n.len() % 3 == 0).then(|| {
                Attr::Points(
                    n.chunks_exact(3)
                        .map(|c| glam::DVec3::new(c[0], c[1], c[2]))
                        .collect(),
                )
            })
        }
        (_, false) if vector => match numbers(tokens, single)?.as_slice() {
            [x, y, z] => Some(Attr::Vec3(glam::DVec3::new(*x, *y, *z))),
            _ => None,
        },
        ("quatd" | "quatf" | "quath", false) => match numbers(tokens, single)?.as_slice() {
            [w, x, y, z] => Some(Attr::quat(*w, *x, *y, *z)),
            _ => None,
        },
        ("matrix4d", false) => {
            let n: [f64; 16] = numbers(tokens, false)?.try_into().ok()?;
            Some(Attr::Matrix(Box::new(glam::DMat4::from_cols_array(&n))))
        }
        (
            "double" | "float" | "half" | "int" | "uint" | "int64" | "uint64" | "uchar"
            | "timecode",
            false,
        ) => match numbers(tokens, single)?.as_slice() {
            [x] => Some(Attr::Scalar(*x)),
            _ => None,
        },
        _ => None,
    }
}

impl Layer {
    /// Whether the layer uses model kinds: a prim of kind `component` reached from the
    /// root through prims with a kind, `Xform`s, `Scope`s or untyped prims (as the
    /// composing reader decides it).
    #[must_use]
    pub(super) fn uses_kinds(&self) -> bool {
        let on_model_path = |p: &LayerPrim| {
            p.kind.is_some() || matches!(p.type_name.as_str(), "Xform" | "Scope" | "")
        };
        let mut stack: Vec<usize> = self.roots.clone();
        while let Some(p) = stack.pop() {
            let prim = &self.prims[p];
            if !on_model_path(prim) {
                continue;
            }
            if prim.kind.as_deref() == Some("component") {
                return true;
            }
            stack.extend(&prim.children);
        }
        false
    }
}
