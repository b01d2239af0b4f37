//! Editing a `.usda` root layer as text: the file is kept byte for byte except the edited
//! prims' transform lines, as scene JSON is written.
//!
//! The layer is scanned once ([`Outline::scan`]) into where each prim spec's body is
//! (`def`, `over` and `class` blocks, outside variant sets) and where its properties'
//! statements are. An edit then, for each moved prim:
//! - replaces its `xformOpOrder` (or adds one) and the `xformOp:…:shenlong` ops an earlier
//!   edit wrote, or adds them at the top of its body;
//! - where the prim has no spec in this layer (it comes from a sublayer or a reference),
//!   adds an `over` for it inside its nearest ancestor's spec, or at the end of the file.
//!
//! Asset paths (`@./set.usda@`) are rewritten when the layer is written to another folder,
//! so that its sublayers, references and payloads still resolve from there.

use super::super::FormatError;
use super::lex::{line_of, Lexer, Token};
use std::collections::{HashMap, HashSet};
use std::path::{Component, Path, PathBuf};

/// Where a prim spec's body is in the text.
#[derive(Clone, Debug)]
struct PrimSpec {
    /// The byte just after its `{`.
    open: usize,
    /// The byte of its `}`.
    close: usize,
    /// The indentation of its statements.
    indent: String,
    /// Its property statements: (name, start byte of the line, end byte after its newline).
    properties: Vec<(String, usize, usize)>,
}

/// A scanned layer: each prim spec by path, and each asset path's span.
#[derive(Debug, Default)]
pub(super) struct Outline {
    prims: HashMap<String, PrimSpec>,
    /// Each prim's property statements (recorded before its spec closes).
    properties: HashMap<String, Vec<(String, usize, usize)>>,
    /// The spans of asset paths, the `@`s included.
    assets: Vec<(usize, usize)>,
}

/// What a block on the scanner's stack is.
#[derive(Clone, Debug)]
enum Block {
    /// A prim's body: its path.
    Prim(String),
    /// Brackets, parentheses, dictionaries, time samples, variant sets (whose prims are
    /// at no plain path).
    Other,
}

/// The scanner's state between tokens.
struct Scanner<'a> {
    text: &'a [u8],
    outline: Outline,
    /// The prims whose specs are recorded (all when `None`).
    keep: Option<&'a HashSet<String>>,
    /// Blocks open, with their bracket.
    stack: Vec<(Block, u8)>,
    /// How many of them are brackets, dictionaries or variant sets (inside one, no
    /// statement of a prim's body is read).
    others: usize,
    /// The statement being read at the current prim level.
    statement: Vec<Token>,
    statement_start: Option<usize>,
    /// A prim header seen, waiting for its `{`: its path.
    pending: Option<String>,
    /// The prims open: each path and the byte after its `{`.
    open_prims: Vec<(String, usize)>,
}

impl Scanner<'_> {
    fn kept(&self, path: &str) -> bool {
        self.keep.is_none_or(|k| k.contains(path))
    }

    fn end_of_statement(&mut self) {
        self.statement.clear();
        self.statement_start = None;
    }

    fn open(&mut self, at: usize, c: u8) -> Result<(), FormatError> {
        if c == b'{' && self.others == 0 && self.pending.is_some() {
            let path = self.pending.take().unwrap_or_default();
            self.open_prims.push((path.clone(), at + 1));
            self.stack.push((Block::Prim(path), c));
            self.end_of_statement();
        } else {
            if self.statement_start.is_none() {
                self.statement_start = Some(at);
            }
            self.stack.push((Block::Other, c));
            self.others += 1;
        }
        if self.stack.len() > super::super::MAX_JSON_DEPTH * 4 {
            return Err(FormatError::too_large(format!(
                "nesting too deep at line {}",
                line_of(self.text, at)
            )));
        }
        Ok(())
    }

    fn close(&mut self, at: usize, c: u8) -> Result<(), FormatError> {
        let opener = match c {
            b'}' => b'{',
            b')' => b'(',
            _ => b'[',
        };
        let Some((block, _)) = self.stack.pop().filter(|(_, open)| *open == opener) else {
            return Err(FormatError::invalid(format!(
                "an unmatched '{}' at line {}",
                c as char,
                line_of(self.text, at)
            )));
        };
        match block {
            Block::Prim(path) => {
                let (_, open) = self.open_prims.pop().unwrap_or_default();
                self.end_of_statement();
                if !self.kept(&path) {
                    return Ok(());
                }
                let indent = indent_of(self.text, open, at);
                self.outline.prims.insert(
                    path,
                    PrimSpec {
                        open,
                        close: at,
                        indent,
                        properties: Vec::new(),
                    },
                );
            }
            Block::Other => self.others -= 1,
        }
        Ok(())
    }

    /// A line ends: a property statement of a prim's body is recorded; a prim header
    /// waits for its `{`.
    fn newline(&mut self, at: usize) {
        if self.others > 0 {
            return;
        }
        self.record_property(at);
        if let Some(path) = prim_header(&self.stack, &self.statement) {
            self.pending = Some(path);
        }
        self.end_of_statement();
    }

    /// Records the property statement that just ended at `end` (a newline) in its prim.
    fn record_property(&mut self, end: usize) {
        let (Some(start), Some((Block::Prim(path), _))) = (self.statement_start, self.stack.last())
        else {
            return;
        };
        if !self.kept(path) {
            return;
        }
        let Some(name) = property_name(&self.statement) else {
            return;
        };
        // Its line, or from the prim's `{` when the statement follows it on that line.
        let body = self.open_prims.last().map_or(0, |(_, open)| *open);
        let line_start = self.text[..start]
            .iter()
            .rposition(|&c| c == b'\n')
            .map_or(0, |p| p + 1)
            .max(body);
        self.outline
            .properties
            .entry(path.clone())
            .or_default()
            .push((name, line_start, end + 1));
    }

    fn word(&mut self, at: usize, token: Token) {
        if self.others > 0 {
            return;
        }
        if self.statement_start.is_none() {
            self.statement_start = Some(at);
        }
        // A header may be followed by `{` on the same line.
        self.statement.push(token);
        if let Some(path) = prim_header(&self.stack, &self.statement) {
            self.pending = Some(path);
        }
    }
}

/// Refuses a layer nested deeper than `max` levels of `{ [ (`, saying where: strings
/// (triple-quoted too), asset paths and comments are read as the scanner reads them, so
/// no quote in a comment (`# it's`) or an asset path hides what follows.
///
/// # Errors
/// Nesting past `max`, or an unclosed string or asset path.
pub(super) fn check_depth(text: &str, max: usize) -> Result<(), FormatError> {
    let t = text.as_bytes();
    let mut lexer = Lexer { text: t, pos: 0 };
    let mut depth = 0usize;
    while let Some((at, token)) = lexer.next()? {
        match token {
            Token::Open(_) => {
                depth += 1;
                if depth > max {
                    return Err(FormatError::too_large(format!(
                        "nesting deeper than {max} levels at line {}",
                        line_of(t, at)
                    )));
                }
            }
            Token::Close(_) => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    Ok(())
}

impl Outline {
    /// Scans a layer's text.
    ///
    /// # Errors
    /// Unbalanced brackets or an unclosed string, saying where.
    pub(super) fn scan(text: &str) -> Result<Self, FormatError> {
        Self::scan_for(text, None)
    }

    /// Scans a layer's text, recording the specs of the prims in `keep` only (all when
    /// `None`): an edit needs its prims' and their ancestors', not the other million.
    ///
    /// # Errors
    /// As [`Outline::scan`].
    fn scan_for(text: &str, keep: Option<&HashSet<String>>) -> Result<Self, FormatError> {
        let t = text.as_bytes();
        let mut lexer = Lexer { text: t, pos: 0 };
        let mut scanner = Scanner {
            text: t,
            outline: Outline::default(),
            keep,
            stack: Vec::new(),
            others: 0,
            statement: Vec::new(),
            statement_start: None,
            pending: None,
            open_prims: Vec::new(),
        };
        while let Some((at, token)) = lexer.next()? {
            match token {
                Token::Asset(a, b) => {
                    scanner.outline.assets.push((a, b));
                    scanner.word(at, Token::Asset(a, b));
                }
                Token::Open(c) => scanner.open(at, c)?,
                Token::Close(c) => scanner.close(at, c)?,
                Token::Newline => scanner.newline(at),
                other => scanner.word(at, other),
            }
        }
        if let Some((_, open)) = scanner.stack.last() {
            return Err(FormatError::invalid(format!(
                "an unclosed '{}' at the end of the layer",
                *open as char
            )));
        }
        Ok(scanner.outline)
    }

    /// The spec of a prim, with its properties.
    fn prim(&self, path: &str) -> Option<PrimSpec> {
        let mut spec = self.prims.get(path)?.clone();
        if let Some(props) = self.properties.get(path) {
            spec.properties.clone_from(props);
        }
        Some(spec)
    }
}

/// The indentation of a body's statements: the first statement line's, else its `}`'s
/// plus four spaces.
fn indent_of(t: &[u8], open: usize, close: usize) -> String {
    let body = &t[open..close];
    for line in body.split(|&c| c == b'\n').skip(1) {
        let trimmed = line.iter().position(|&c| c != b' ' && c != b'\t');
        if let Some(k) = trimmed {
            if !matches!(line[k], b'}' | b'#') {
                return String::from_utf8_lossy(&line[..k]).into_owned();
            }
        }
    }
    let line_start = t[..close]
        .iter()
        .rposition(|&c| c == b'\n')
        .map_or(0, |p| p + 1);
    let closing: String = t[line_start..close]
        .iter()
        .take_while(|&&c| c == b' ' || c == b'\t')
        .map(|&c| c as char)
        .collect();
    format!("{closing}    ")
}

/// The path of a prim whose header `statement` is (`def Xform "Chair"`, `over "World"`),
/// under the prim whose body is on top of `stack`.
fn prim_header(stack: &[(Block, u8)], statement: &[Token]) -> Option<String> {
    let parent = match stack.last() {
        None => String::new(),
        Some((Block::Prim(p), _)) => p.clone(),
        Some(_) => return None,
    };
    let Some(Token::Word(first)) = statement.first() else {
        return None;
    };
    if !matches!(first.as_str(), "def" | "over" | "class") {
        return None;
    }
    let name = statement.iter().skip(1).take(2).find_map(|t| match t {
        Token::Str(s) => Some(s.clone()),
        _ => None,
    })?;
    Some(format!("{parent}/{name}"))
}

/// The name of the property a statement declares (`uniform token[] xformOpOrder = …`,
/// `double3 xformOp:translate:shenlong = …`, `rel material:binding = …`).
fn property_name(statement: &[Token]) -> Option<String> {
    let words: Vec<&str> = statement
        .iter()
        .map_while(|t| match t {
            Token::Word(w) => Some(w.as_str()),
            Token::Punct(b'[') | Token::Open(b'[') => Some("[]"),
            Token::Close(b']') => Some(""),
            _ => None,
        })
        .filter(|w| !w.is_empty() && *w != "[]")
        .collect();
    if matches!(
        words.first(),
        Some(&("def" | "over" | "class" | "variantSet"))
    ) {
        return None;
    }
    words.last().map(|w| {
        w.trim_end_matches(".timeSamples")
            .trim_end_matches(".connect")
            .to_string()
    })
}

/// One prim's new ops: (name, USD type, value as text), in order. An op of no type is
/// named in the order only ([`RESET`]).
pub(super) type Ops = Vec<(String, &'static str, String)>;

/// The op-order entry that resets the transform stack.
pub(super) const RESET: &str = "!resetXformStack!";

/// Whether a property is one this edit replaces: the order, or an op an earlier edit of
/// Shenlong's wrote.
fn replaced(name: &str) -> bool {
    name == "xformOpOrder" || (name.starts_with("xformOp:") && name.ends_with(":shenlong"))
}

/// A layer moving from one folder to another (both canonical): its relative asset paths
/// are rewritten to resolve from the new one.
#[derive(Debug)]
pub(super) struct Move {
    /// The folder the layer was read from.
    pub from: PathBuf,
    /// The folder it is written to.
    pub to: PathBuf,
}

/// A replacement in the layer's text: bytes `.0..1` become `.2`.
type Change = (usize, usize, String);

/// The layer's text with each prim's new ops (`edits`, by path), and its relative asset
/// paths rewritten when it `moves` to another folder.
///
/// # Errors
/// The text cannot be scanned.
pub(super) fn patch(
    text: &str,
    edits: &[(String, Ops)],
    moves: Option<&Move>,
) -> Result<String, FormatError> {
    // The edited prims and their ancestors: the only specs the edit looks at.
    let mut keep: HashSet<String> = HashSet::new();
    for (path, _) in edits {
        let mut p = path.as_str();
        while !p.is_empty() && keep.insert(p.to_string()) {
            p = p.rsplit_once('/').map_or("", |(parent, _)| parent);
        }
    }
    let outline = Outline::scan_for(text, Some(&keep))?;
    let mut changes: Vec<Change> = Vec::new();
    let mut appended: Vec<(String, Ops)> = Vec::new();
    for (path, ops) in edits {
        match outline.prim(path) {
            Some(spec) => changes.extend(ops_in_spec(text, &spec, ops)),
            None => appended.push((path.clone(), ops.clone())),
        }
    }
    changes.extend(overs(text, &outline, appended));
    if let Some(m) = moves {
        changes.extend(moved_assets(text, &outline, m));
    }
    Ok(apply(text, changes))
}

/// The change that writes `ops` into a prim's own spec: over its first transform
/// property (the others removed), or, with none, at the top of its body.
fn ops_in_spec(text: &str, spec: &PrimSpec, ops: &Ops) -> Vec<Change> {
    let lines = op_lines(ops, &spec.indent);
    let mut changes = Vec::new();
    for (name, start, end) in &spec.properties {
        if replaced(name) {
            let new = if changes.is_empty() {
                lines.clone()
            } else {
                String::new()
            };
            changes.push((*start, *end, new));
        }
    }
    if changes.is_empty() {
        let at = line_after(text.as_bytes(), spec.open);
        if text[spec.open..at].trim().is_empty() {
            changes.push((at, at, lines));
        } else {
            // Something follows the `{` on its line: the ops go right after it.
            changes.push((spec.open, spec.open, format!("\n{lines}")));
        }
    }
    changes
}

/// For prims with no spec in this layer: `over`s inside the nearest ancestor's spec, or
/// at the end of the layer.
fn overs(text: &str, outline: &Outline, appended: Vec<(String, Ops)>) -> Vec<Change> {
    let mut by_ancestor: HashMap<Option<String>, Vec<(String, Ops)>> = HashMap::new();
    for (path, ops) in appended {
        let mut ancestor = None;
        let mut p = path.as_str();
        while let Some((parent, _)) = p.rsplit_once('/') {
            if parent.is_empty() {
                break;
            }
            if outline.prims.contains_key(parent) {
                ancestor = Some(parent.to_string());
                break;
            }
            p = parent;
        }
        by_ancestor.entry(ancestor).or_default().push((path, ops));
    }
    let mut changes = Vec::new();
    for (ancestor, list) in by_ancestor {
        let (at, indent, base) = match &ancestor {
            Some(a) => {
                let spec = outline.prim(a).unwrap_or_else(|| PrimSpec {
                    open: text.len(),
                    close: text.len(),
                    indent: String::new(),
                    properties: Vec::new(),
                });
                let line = text[..spec.close].rfind('\n').map_or(0, |p| p + 1);
                // Where the `}` shares its line with other text (`def "A" {}`), the over
                // goes right before the `}`, on lines of its own.
                let at = if text[line..spec.close].trim().is_empty() {
                    line
                } else {
                    spec.close
                };
                (at, spec.indent, a.clone())
            }
            None => (text.len(), String::new(), String::new()),
        };
        let mut block = String::new();
        if ancestor.is_none() && !text.ends_with('\n') {
            block.push('\n');
        }
        let mut tree = Overs::default();
        for (path, ops) in list {
            tree.insert(path.strip_prefix(&base).unwrap_or(&path), ops);
        }
        tree.write(&mut block, &indent);
        changes.push((at, at, block));
    }
    changes
}

/// The layer's relative asset paths, rewritten for its new folder.
fn moved_assets(text: &str, outline: &Outline, m: &Move) -> Vec<Change> {
    let mut changes = Vec::new();
    for &(a, b) in &outline.assets {
        let inner = &text[a..b];
        let (open, path) = if inner.starts_with("@@@") {
            ("@@@", &inner[3..inner.len().saturating_sub(3)])
        } else {
            ("@", &inner[1..inner.len().saturating_sub(1)])
        };
        if let Some(new) = relocated(path, &m.from, &m.to) {
            changes.push((a, b, format!("{open}{new}{open}")));
        }
    }
    changes
}

/// `text` with `changes` made, front to back; a change overlapping an earlier one is
/// dropped.
fn apply(text: &str, mut changes: Vec<Change>) -> String {
    changes.sort_by_key(|c| (c.0, c.1));
    let mut out = String::with_capacity(text.len() + 256);
    let mut cursor = 0;
    for (start, end, new) in changes {
        if start < cursor {
            continue;
        }
        out.push_str(&text[cursor..start]);
        out.push_str(&new);
        cursor = end;
    }
    out.push_str(&text[cursor..]);
    out
}

/// The byte after the line that holds `at` (where a body's first statement goes).
fn line_after(t: &[u8], at: usize) -> usize {
    t[at..]
        .iter()
        .position(|&c| c == b'\n')
        .map_or(t.len(), |p| at + p + 1)
}

/// The ops' statements and their order, each on its own line at `indent`.
fn op_lines(ops: &Ops, indent: &str) -> String {
    let mut s = String::new();
    for (name, type_name, value) in ops.iter().filter(|(_, t, _)| !t.is_empty()) {
        s.push_str(&format!("{indent}{type_name} {name} = {value}\n"));
    }
    let order: Vec<String> = ops.iter().map(|(n, _, _)| format!("\"{n}\"")).collect();
    s.push_str(&format!(
        "{indent}uniform token[] xformOpOrder = [{}]\n",
        order.join(", ")
    ));
    s
}

/// Prims with no spec in a layer, as a tree of `over`s holding their new ops: prims that
/// share an ancestor share its `over` (a layer may hold one spec of a prim).
#[derive(Debug, Default)]
pub(super) struct Overs {
    children: Vec<(String, Overs)>,
    ops: Ops,
}

impl Overs {
    /// Adds the prim at `path` (relative to where the tree is written) with its ops.
    pub(super) fn insert(&mut self, path: &str, ops: Ops) {
        let mut node = self;
        for name in path.split('/').filter(|s| !s.is_empty()) {
            let k = match node.children.iter().position(|(n, _)| n == name) {
                Some(k) => k,
                None => {
                    node.children.push((name.to_string(), Overs::default()));
                    node.children.len() - 1
                }
            };
            node = &mut node.children[k].1;
        }
        node.ops = ops;
    }

    /// The tree as text at `indent`, each top-level `over` after a blank line; a stack,
    /// never recursion.
    pub(super) fn write(&self, out: &mut String, indent: &str) {
        enum Step<'a> {
            Open(&'a str, &'a Overs, usize),
            Close(usize),
        }
        let mut stack: Vec<Step<'_>> = self
            .children
            .iter()
            .rev()
            .map(|(n, t)| Step::Open(n, t, 0))
            .collect();
        while let Some(step) = stack.pop() {
            match step {
                Step::Open(name, node, depth) => {
                    let pad = format!("{indent}{}", "    ".repeat(depth));
                    if depth == 0 {
                        out.push('\n');
                    }
                    out.push_str(&format!("{pad}over \"{}\"\n{pad}{{\n", super::escape(name)));
                    if !node.ops.is_empty() {
                        out.push_str(&op_lines(&node.ops, &format!("{pad}    ")));
                    }
                    stack.push(Step::Close(depth));
                    for (n, t) in node.children.iter().rev() {
                        stack.push(Step::Open(n, t, depth + 1));
                    }
                }
                Step::Close(depth) => {
                    out.push_str(&format!("{indent}{}}}\n", "    ".repeat(depth)));
                }
            }
        }
    }
}

/// How an asset path of a layer in `from` is written for the same layer in `to`: a
/// relative path (`./x`, `../x`, `x`) made relative to `to` (with `./` or `../`), when the
/// file it names exists; absolute paths, URLs and paths that name nothing are kept.
#[must_use]
pub(super) fn relocated(path: &str, from: &Path, to: &Path) -> Option<String> {
    if path.is_empty() || path.contains("://") || Path::new(path).is_absolute() {
        return None;
    }
    // A path into a package (`a.usdz[b.usda]`) relocates by its package.
    let (outer, inner) = match path.find('[') {
        Some(k) => (&path[..k], &path[k..]),
        None => (path, ""),
    };
    let target = from.join(outer).canonicalize().ok()?;
    let rel = relative(to, &target)?;
    Some(format!("{rel}{inner}"))
}

/// `target` relative to the folder `base` (both canonical), as `./a/b` or `../a/b`.
fn relative(base: &Path, target: &Path) -> Option<String> {
    let b: Vec<Component<'_>> = base.components().collect();
    let t: Vec<Component<'_>> = target.components().collect();
    let common = b.iter().zip(&t).take_while(|(x, y)| x == y).count();
    if common == 0 {
        return None;
    }
    let mut out = PathBuf::new();
    for _ in common..b.len() {
        out.push("..");
    }
    for c in &t[common..] {
        out.push(c.as_os_str());
    }
    let s = out.to_str()?.replace('\\', "/");
    Some(if s.starts_with("..") {
        s
    } else {
        format!("./{s}")
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const LAYER: &str = r#"#usda 1.0
(
    defaultPrim = "World"
    doc = """it's a "doc" { with braces"""
)

def Xform "World"
{
    def Xform "Chair" (
        prepend apiSchemas = ["MaterialBindingAPI"]
    )
    {
        double3 xformOp:translate = (1, 0, 0)
        uniform token[] xformOpOrder = ["xformOp:translate"]
        rel material:binding = </World/Looks/Wood>
        # a comment with a { brace
    }

    variantSet "look" = {
        "red" {
            def Xform "Chair" {}
        }
    }
}
"#;

    fn ops() -> Ops {
        vec![(
            "xformOp:translate:shenlong".to_string(),
            "double3",
            "(2, 0, 0)".to_string(),
        )]
    }

    #[test]
    fn only_the_edited_prims_lines_change() {
        let out = patch(LAYER, &[("/World/Chair".into(), ops())], None).unwrap();
        let removed: Vec<&str> = LAYER.lines().filter(|l| !out.contains(l)).collect();
        assert_eq!(
            removed,
            ["        uniform token[] xformOpOrder = [\"xformOp:translate\"]"]
        );
        assert!(out.contains(
            "        double3 xformOp:translate:shenlong = (2, 0, 0)\n        uniform token[] xformOpOrder = [\"xformOp:translate:shenlong\"]\n        rel material:binding"
        ));
        // Edited again: the earlier ops are replaced, not repeated.
        let again = patch(&out, &[("/World/Chair".into(), ops())], None).unwrap();
        assert_eq!(again, out);
    }

    #[test]
    fn a_prim_from_another_layer_gets_an_over() {
        let out = patch(LAYER, &[("/World/Table/Top".into(), ops())], None).unwrap();
        assert!(out.contains("    over \"Table\"\n    {\n        over \"Top\"\n        {\n            double3 xformOp:translate:shenlong"), "{out}");
        let out = patch(LAYER, &[("/Other".into(), ops())], None).unwrap();
        assert!(out.ends_with("over \"Other\"\n{\n    double3 xformOp:translate:shenlong = (2, 0, 0)\n    uniform token[] xformOpOrder = [\"xformOp:translate:shenlong\"]\n}\n"), "{out}");
    }

    #[test]
    fn prims_from_another_layer_under_one_ancestor_share_its_over() {
        // The root layer has no `World`: two prims under it get one `over "World"` (two
        // specs of one prim in a layer would not open).
        let header = "#usda 1.0\n(\n    subLayers = [@./set.usda@]\n)\n";
        let out = patch(
            header,
            &[("/World/A".into(), ops()), ("/World/B".into(), ops())],
            None,
        )
        .unwrap();
        assert_eq!(out.matches("over \"World\"").count(), 1, "{out}");
        let outline = Outline::scan(&out).unwrap();
        assert!(outline.prims.contains_key("/World/A") && outline.prims.contains_key("/World/B"));
    }

    #[test]
    fn headers_and_bodies_on_one_line_keep_their_prims() {
        // A property on the `{` line: only it is replaced, the header stays.
        let one_line = "#usda 1.0\ndef Xform \"A\" { uniform token[] xformOpOrder = [\"xformOp:translate\"]\n}\n";
        let out = patch(one_line, &[("/A".into(), ops())], None).unwrap();
        assert!(out.starts_with("#usda 1.0\ndef Xform \"A\" {"), "{out}");
        assert!(Outline::scan(&out).is_ok(), "{out}");
        // An over for a child of a prim written on one line goes inside it.
        let compact = "#usda 1.0\ndef Xform \"World\" {}\n";
        let out = patch(compact, &[("/World/Chair".into(), ops())], None).unwrap();
        let outline = Outline::scan(&out).unwrap();
        assert!(outline.prims.contains_key("/World/Chair"), "{out}");
        // A prim that resets the transform stack keeps the reset first in its order.
        let reset: Ops = vec![
            (RESET.to_string(), "", String::new()),
            (
                "xformOp:translate:shenlong".into(),
                "double3",
                "(1, 0, 0)".into(),
            ),
        ];
        let out = patch(LAYER, &[("/World/Chair".into(), reset)], None).unwrap();
        assert!(
            out.contains("xformOpOrder = [\"!resetXformStack!\", \"xformOp:translate:shenlong\"]"),
            "{out}"
        );
        assert!(!out.contains(" !resetXformStack! ="), "{out}");
    }

    #[test]
    fn depth_is_counted_past_comments_triple_quotes_and_asset_paths() {
        let deep = format!(
            "#usda 1.0\n# it's\n(doc = \"\"\"a \" b\"\"\")\n@it's.usda@\n{}",
            "{".repeat(101)
        );
        let e = check_depth(&deep, 100).unwrap_err();
        assert!(
            e.to_string()
                .contains("nesting deeper than 100 levels at line 5"),
            "{}",
            e.to_string()
        );
        assert!(check_depth("#usda 1.0\n(\n)\n", 100).is_ok());
        assert!(Outline::scan("#usda 1.0\ndef \"A\" (\n}\n").is_err());
    }

    #[test]
    fn unbalanced_text_is_refused_with_where() {
        let e = Outline::scan("#usda 1.0\ndef \"A\" {\n").unwrap_err();
        assert!(e.to_string().contains("unclosed '{'"), "{}", e.to_string());
        let e = Outline::scan("#usda 1.0\ndef \"A\" {}\n}\n").unwrap_err();
        assert!(e.to_string().contains("line 3"), "{}", e.to_string());
    }

    #[test]
    fn relative_paths() {
        assert_eq!(
            relative(Path::new("/a/b"), Path::new("/a/c/d.usda")).as_deref(),
            Some("../c/d.usda")
        );
        assert_eq!(
            relative(Path::new("/a"), Path::new("/a/c/d.usda")).as_deref(),
            Some("./c/d.usda")
        );
    }
}
