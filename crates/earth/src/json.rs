//! A strict JSON reader (RFC 8259) that remembers where every value and key starts, for
//! input errors that name their line. Not a paper function: the scenario format's reader
//! (paper B's areas and tracks) and the report merges use it.
//!
//! What it adds to a plain reader:
//! - every [`Node`] and object key carries its byte offset, and [`Lines`] turns an offset
//!   into a 1-based line and column;
//! - an object keeps all its members in order, a key given twice included, so that the
//!   reader of a format can call it an error for the one feature that has it (the rest
//!   of the file is still read);
//! - `NaN`, `Infinity` and `-Infinity`, which Python's `json` writes but JSON lacks, are
//!   read as [`Json::NotJson`] for the same reason: an error for their field only;
//! - a byte-order mark at the start is skipped.
//!
//! Numbers are read as the nearest f64 (Rust's `f64::from_str` rounds correctly); one
//! too large for an f64 reads as ±∞, which the formats reject by field.

use std::fmt;

/// Nesting deeper than this is an error (the reader recurses).
pub const MAX_DEPTH: usize = 256;

/// A value and where it starts (a byte offset into the text).
#[derive(Clone, Debug, PartialEq)]
pub struct Node {
    /// Byte offset of the value's first character.
    pub at: usize,
    /// The value.
    pub value: Json,
}

/// One member of an object.
#[derive(Clone, Debug, PartialEq)]
pub struct Member {
    /// The key, unescaped.
    pub key: String,
    /// Byte offset of the key's opening quote.
    pub at: usize,
    /// The value.
    pub value: Node,
}

/// A JSON value.
#[derive(Clone, Debug, PartialEq)]
pub enum Json {
    /// `null`.
    Null,
    /// `true` or `false`.
    Bool(bool),
    /// The nearest f64 (±∞ when beyond the f64 range).
    Number(f64),
    /// `NaN`, `Infinity` or `-Infinity`: not JSON, kept to be named by the reader.
    NotJson(&'static str),
    /// A string, unescaped.
    String(String),
    /// Elements in order.
    Array(Vec<Node>),
    /// Members in order, repeated keys included.
    Object(Vec<Member>),
}

impl Json {
    /// What kind of value this is, for "expected …, found …" messages.
    pub fn kind(&self) -> &'static str {
        match self {
            Json::Null => "null",
            Json::Bool(_) => "a boolean",
            Json::Number(_) | Json::NotJson(_) => "a number",
            Json::String(_) => "a string",
            Json::Array(_) => "an array",
            Json::Object(_) => "an object",
        }
    }
}

impl Node {
    /// The members when this is an object.
    pub fn members(&self) -> Option<&[Member]> {
        match &self.value {
            Json::Object(m) => Some(m),
            _ => None,
        }
    }
    /// The elements when this is an array.
    pub fn elements(&self) -> Option<&[Node]> {
        match &self.value {
            Json::Array(a) => Some(a),
            _ => None,
        }
    }
    /// The text when this is a string.
    pub fn as_str(&self) -> Option<&str> {
        match &self.value {
            Json::String(s) => Some(s),
            _ => None,
        }
    }
    /// The first member named `key` when this is an object.
    pub fn get(&self, key: &str) -> Option<&Node> {
        self.members()?
            .iter()
            .find(|m| m.key == key)
            .map(|m| &m.value)
    }
}

/// A text that is not JSON: where, and why.
#[derive(Clone, Debug, PartialEq)]
pub struct SyntaxError {
    /// Byte offset of the problem.
    pub at: usize,
    /// What is wrong.
    pub message: String,
}

impl fmt::Display for SyntaxError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

/// Line starts of a text, to turn byte offsets into 1-based lines and columns.
#[derive(Clone, Debug)]
pub struct Lines {
    starts: Vec<usize>,
}

impl Lines {
    /// The line table of `text`.
    pub fn new(text: &str) -> Self {
        let mut starts = vec![0];
        starts.extend(text.match_indices('\n').map(|(i, _)| i + 1));
        Lines { starts }
    }
    /// The 1-based line of a byte offset.
    pub fn line(&self, at: usize) -> usize {
        self.starts.partition_point(|&s| s <= at)
    }
    /// The 1-based line and (byte) column of an offset.
    pub fn line_col(&self, at: usize) -> (usize, usize) {
        let line = self.line(at);
        (line, at - self.starts[line - 1] + 1)
    }
}

/// Reads a whole text as one JSON value (a byte-order mark in front is skipped; only
/// whitespace may follow the value).
pub fn parse(text: &str) -> Result<Node, SyntaxError> {
    let start = if text.starts_with('\u{feff}') { 3 } else { 0 };
    let mut r = Reader {
        s: text.as_bytes(),
        i: start,
        text,
    };
    let v = r.value(0)?;
    r.ws();
    if r.i < r.s.len() {
        return Err(r.err("unexpected text after the JSON value"));
    }
    Ok(v)
}

struct Reader<'a> {
    s: &'a [u8],
    i: usize,
    text: &'a str,
}

impl Reader<'_> {
    fn err(&self, message: impl Into<String>) -> SyntaxError {
        SyntaxError {
            at: self.i.min(self.s.len()),
            message: message.into(),
        }
    }

    fn ws(&mut self) {
        while let Some(b' ' | b'\t' | b'\n' | b'\r') = self.s.get(self.i) {
            self.i += 1;
        }
    }

    fn found(&self) -> String {
        match self.text.get(self.i..).and_then(|t| t.chars().next()) {
            Some(c) => format!("found {c:?}"),
            None => String::from("found the end of the text"),
        }
    }

    fn value(&mut self, depth: usize) -> Result<Node, SyntaxError> {
        if depth > MAX_DEPTH {
            return Err(self.err(format!("nested deeper than {MAX_DEPTH} levels")));
        }
        self.ws();
        let at = self.i;
        let rest = &self.s[self.i..];
        let lit = |w: &str| rest.starts_with(w.as_bytes());
        let value = match rest.first() {
            Some(b'{') => self.object(depth)?,
            Some(b'[') => self.array(depth)?,
            Some(b'"') => Json::String(self.string()?),
            Some(b'-' | b'0'..=b'9') if !lit("-Infinity") => self.number()?,
            _ => {
                let words: [(&str, Json); 6] = [
                    ("null", Json::Null),
                    ("true", Json::Bool(true)),
                    ("false", Json::Bool(false)),
                    ("NaN", Json::NotJson("NaN")),
                    ("Infinity", Json::NotJson("Infinity")),
                    ("-Infinity", Json::NotJson("-Infinity")),
                ];
                match words.into_iter().find(|(w, _)| lit(w)) {
                    Some((w, v)) => {
                        self.i += w.len();
                        v
                    }
                    None => return Err(self.err(format!("expected a value, {}", self.found()))),
                }
            }
        };
        Ok(Node { at, value })
    }

    fn object(&mut self, depth: usize) -> Result<Json, SyntaxError> {
        self.i += 1;
        let mut members = Vec::new();
        self.ws();
        if self.s.get(self.i) == Some(&b'}') {
            self.i += 1;
            return Ok(Json::Object(members));
        }
        loop {
            self.ws();
            let at = self.i;
            if self.s.get(self.i) != Some(&b'"') {
                return Err(self.err(format!("expected a key in quotes, {}", self.found())));
            }
            let key = self.string()?;
            self.ws();
            if self.s.get(self.i) != Some(&b':') {
                return Err(self.err(format!("expected ':' after a key, {}", self.found())));
            }
            self.i += 1;
            let value = self.value(depth + 1)?;
            members.push(Member { key, at, value });
            self.ws();
            match self.s.get(self.i) {
                Some(b',') => self.i += 1,
                Some(b'}') => {
                    self.i += 1;
                    return Ok(Json::Object(members));
                }
                _ => {
                    return Err(self.err(format!(
                        "expected ',' or '}}' in an object, {}",
                        self.found()
                    )))
                }
            }
        }
    }

    fn array(&mut self, depth: usize) -> Result<Json, SyntaxError> {
        self.i += 1;
        let mut items = Vec::new();
        self.ws();
        if self.s.get(self.i) == Some(&b']') {
            self.i += 1;
            return Ok(Json::Array(items));
        }
        loop {
            items.push(self.value(depth + 1)?);
            self.ws();
            match self.s.get(self.i) {
                Some(b',') => self.i += 1,
                Some(b']') => {
                    self.i += 1;
                    return Ok(Json::Array(items));
                }
                _ => {
                    return Err(
                        self.err(format!("expected ',' or ']' in an array, {}", self.found()))
                    )
                }
            }
        }
    }

    fn hex4(&mut self) -> Result<u32, SyntaxError> {
        let h = self
            .text
            .get(self.i..self.i + 4)
            .filter(|h| h.bytes().all(|b| b.is_ascii_hexdigit()))
            .ok_or_else(|| self.err("\\u must be followed by four hex digits"))?;
        self.i += 4;
        u32::from_str_radix(h, 16).map_err(|_| self.err("bad \\u escape"))
    }

    fn string(&mut self) -> Result<String, SyntaxError> {
        self.i += 1; // the opening quote
        let mut out = String::new();
        loop {
            // copy the run up to the next quote, backslash or control character
            let run = self.s[self.i..]
                .iter()
                .position(|&b| b == b'"' || b == b'\\' || b < 0x20)
                .ok_or_else(|| {
                    let mut e = self.err("a string is not closed");
                    e.at = self.s.len();
                    e
                })?;
            // the text is a &str and the run ends at an ASCII byte: a char boundary
            out.push_str(&self.text[self.i..self.i + run]);
            self.i += run;
            match self.s[self.i] {
                b'"' => {
                    self.i += 1;
                    return Ok(out);
                }
                b'\\' => {
                    self.i += 1;
                    let c = match self.s.get(self.i) {
                        Some(b'"') => '"',
                        Some(b'\\') => '\\',
                        Some(b'/') => '/',
                        Some(b'b') => '\u{8}',
                        Some(b'f') => '\u{c}',
                        Some(b'n') => '\n',
                        Some(b'r') => '\r',
                        Some(b't') => '\t',
                        Some(b'u') => {
                            self.i += 1;
                            let hi = self.hex4()?;
                            let code = if (0xD800..0xDC00).contains(&hi) {
                                if !self.s[self.i..].starts_with(b"\\u") {
                                    return Err(self.err("a lone surrogate in \\u escapes"));
                                }
                                self.i += 2;
                                let lo = self.hex4()?;
                                if !(0xDC00..0xE000).contains(&lo) {
                                    return Err(self.err("a lone surrogate in \\u escapes"));
                                }
                                0x10000 + ((hi - 0xD800) << 10) + (lo - 0xDC00)
                            } else {
                                hi
                            };
                            out.push(
                                char::from_u32(code)
                                    .ok_or_else(|| self.err("a lone surrogate in \\u escapes"))?,
                            );
                            continue;
                        }
                        _ => return Err(self.err("an unknown escape after '\\'")),
                    };
                    self.i += 1;
                    out.push(c);
                }
                _ => return Err(self.err("a control character inside a string (escape it)")),
            }
        }
    }

    fn number(&mut self) -> Result<Json, SyntaxError> {
        let start = self.i;
        let digits = |r: &mut Self| {
            let n = r.s[r.i..].iter().take_while(|b| b.is_ascii_digit()).count();
            r.i += n;
            n
        };
        if self.s.get(self.i) == Some(&b'-') {
            self.i += 1;
        }
        let int_start = self.i;
        if digits(self) == 0 {
            return Err(self.err("a number needs digits"));
        }
        if self.s[int_start] == b'0' && self.i - int_start > 1 {
            self.i = int_start + 1;
            return Err(self.err("a number must not start with 0"));
        }
        if self.s.get(self.i) == Some(&b'.') {
            self.i += 1;
            if digits(self) == 0 {
                return Err(self.err("a digit must follow the decimal point"));
            }
        }
        if let Some(b'e' | b'E') = self.s.get(self.i) {
            self.i += 1;
            if let Some(b'+' | b'-') = self.s.get(self.i) {
                self.i += 1;
            }
            if digits(self) == 0 {
                return Err(self.err("an exponent needs digits"));
            }
        }
        self.text[start..self.i]
            .parse::<f64>()
            .map(Json::Number)
            .map_err(|_| self.err("not a number"))
    }
}

/// The first key given twice in any object of the tree (depth first): its path
/// (`a.b[2].c`) and offset.
pub fn repeated_key(n: &Node) -> Option<(String, usize)> {
    fn walk(n: &Node, path: &str) -> Option<(String, usize)> {
        match &n.value {
            Json::Object(m) => {
                let mut seen = std::collections::HashSet::with_capacity(m.len());
                for mem in m {
                    let p = if path.is_empty() {
                        mem.key.clone()
                    } else {
                        format!("{path}.{}", mem.key)
                    };
                    if !seen.insert(mem.key.as_str()) {
                        return Some((p, mem.at));
                    }
                    if let Some(r) = walk(&mem.value, &p) {
                        return Some(r);
                    }
                }
                None
            }
            Json::Array(a) => a
                .iter()
                .enumerate()
                .find_map(|(k, x)| walk(x, &format!("{path}[{k}]"))),
            _ => None,
        }
    }
    walk(n, "")
}

/// The defined name that an unknown `key` most likely misspells: the name with its unit
/// (`course` for `course_deg`), the same letters in another case, or at most three edits
/// away and fewer than half its letters.
pub fn suggest(key: &str, known: &[&'static str]) -> Option<&'static str> {
    // A name given without its unit (`course` for `course_deg`, `buff` for `buff_nm`).
    let lower = key.to_lowercase();
    if let Some(&k) = known.iter().find(|k| {
        k.strip_prefix(lower.as_str())
            .is_some_and(|rest| rest.starts_with('_'))
    }) {
        return Some(k);
    }
    known
        .iter()
        .map(|&k| (edit_distance(&key.to_lowercase(), k), k))
        .filter(|&(d, k)| d <= 3 && 2 * d < k.len().max(key.len()))
        .min_by_key(|&(d, _)| d)
        .map(|(_, k)| k)
}

/// Levenshtein distance (insertions, deletions, substitutions), by characters.
pub fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let here = row[j + 1];
            row[j + 1] = (prev + usize::from(ca != cb)).min(row[j] + 1).min(here + 1);
            prev = here;
        }
    }
    row[b.len()]
}

/// A JSON value as serde_json's tree (`NaN`/`Infinity` as null): what a format keeps
/// of members it does not read.
pub fn to_value(n: &Node) -> serde_json::Value {
    match &n.value {
        Json::Null | Json::NotJson(_) => serde_json::Value::Null,
        Json::Bool(b) => (*b).into(),
        Json::Number(x) => (*x).into(),
        Json::String(s) => s.clone().into(),
        Json::Array(a) => a.iter().map(to_value).collect(),
        Json::Object(m) => m
            .iter()
            .map(|m| (m.key.clone(), to_value(&m.value)))
            .collect::<serde_json::Map<_, _>>()
            .into(),
    }
}

#[cfg(test)]
mod tests {

    #[test]
    fn a_name_without_its_unit_is_suggested_with_it() {
        let known = ["lookahead_h", "buff_nm", "course_deg", "speed_kn"];
        assert_eq!(suggest("course", &known), Some("course_deg"));
        assert_eq!(suggest("Buff", &known), Some("buff_nm"));
        assert_eq!(suggest("speed_kts", &known), Some("speed_kn"));
        assert_eq!(suggest("colour", &known), None);
    }

    use super::*;

    #[test]
    fn values_and_offsets() {
        let t = "\u{feff}{\"a\": [1, -2.5e3, true, null],\n \"b\": \"x\\u00e9\\ud83d\\ude00\"}";
        let v = parse(t).expect("json");
        let a = v.get("a").expect("a");
        assert_eq!(
            a.elements().map(|e| e.len()),
            Some(4),
            "four elements in {a:?}"
        );
        assert_eq!(a.elements().expect("a")[1].value, Json::Number(-2500.0));
        let b = v.get("b").expect("b");
        assert_eq!(b.as_str(), Some("xé😀"));
        let lines = Lines::new(t);
        assert_eq!(lines.line_col(b.at), (2, 7));
    }

    #[test]
    fn repeated_keys_and_non_json_numbers_are_kept() {
        let v = parse(r#"{"k": 1, "k": NaN, "m": -Infinity}"#).expect("json");
        let m = v.members().expect("object");
        assert_eq!(m.len(), 3);
        assert_eq!(m[1].value.value, Json::NotJson("NaN"));
        assert_eq!(m[2].value.value, Json::NotJson("-Infinity"));
    }

    #[test]
    fn numbers_round_to_nearest_and_overflow_to_infinity() {
        let v = parse("[0.1, 1e400, 5e-324, 2.4703282292062328e-324]").expect("json");
        let xs: Vec<Json> = v
            .elements()
            .expect("array")
            .iter()
            .map(|n| n.value.clone())
            .collect();
        assert_eq!(xs[0], Json::Number(0.1));
        assert_eq!(xs[1], Json::Number(f64::INFINITY));
        assert_eq!(xs[2], Json::Number(5e-324));
        assert_eq!(xs[3], Json::Number(5e-324));
    }

    #[test]
    fn syntax_errors_say_where() {
        for (text, at, what) in [
            ("{\"a\": 1,}", 8, "expected a key"),
            ("[1 2]", 3, "expected ','"),
            ("[01]", 2, "must not start with 0"),
            ("\"abc", 4, "not closed"),
            ("{\"a\" 1}", 5, "expected ':'"),
            ("[1] x", 4, "after the JSON value"),
            ("[1.]", 3, "decimal point"),
            ("[nul]", 1, "expected a value"),
        ] {
            let e = parse(text).expect_err(text);
            assert_eq!(e.at, at, "{text}: {e:?}");
            assert!(e.message.contains(what), "{text}: {e:?}");
        }
        let deep = "[".repeat(MAX_DEPTH + 2);
        assert!(parse(&deep).expect_err("deep").message.contains("nested"));
    }

    /// Agrees with serde_json on what is JSON (outside the NaN/Infinity extension and
    /// repeated keys), value for value.
    #[test]
    fn agrees_with_serde_json() {
        for text in [
            r#"{"type":"FeatureCollection","features":[{"a":[1.5,-0.0,1e-7]}]}"#,
            r#"[ "\t\"\\\/", 123456789012345678901234567890, {} , [] ]"#,
            "  3.25  ",
        ] {
            // numbers compared as f64 (serde_json keeps integers apart)
            fn norm(v: serde_json::Value) -> serde_json::Value {
                match v {
                    serde_json::Value::Number(n) => n.as_f64().into(),
                    serde_json::Value::Array(a) => a.into_iter().map(norm).collect(),
                    serde_json::Value::Object(m) => {
                        m.into_iter().map(|(k, v)| (k, norm(v))).collect()
                    }
                    v => v,
                }
            }
            let ours = norm(to_value(&parse(text).expect(text)));
            let theirs = norm(serde_json::from_str(text).expect(text));
            assert_eq!(ours, theirs, "{text}");
        }
    }
}
