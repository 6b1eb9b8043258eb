//! Shared helpers of the CLI tests: scratch directories, small generated meshes, running the
//! built `lamella` binary, and a well-formedness check for XML.
#![allow(dead_code)] // Each test file uses a different subset.

use lamella::surfaces::hall_roof;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::atomic::{AtomicUsize, Ordering};

static NEXT: AtomicUsize = AtomicUsize::new(0);

/// A fresh, empty scratch directory (removed on drop).
pub struct Scratch(pub PathBuf);

impl Scratch {
    pub fn new(tag: &str) -> Scratch {
        let n = NEXT.fetch_add(1, Ordering::Relaxed);
        let dir = std::env::temp_dir().join(format!("lamella-cli-{tag}-{}-{n}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).expect("scratch dir");
        Scratch(dir)
    }

    pub fn path(&self, name: &str) -> PathBuf {
        self.0.join(name)
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Writes a small hall roof (about `vertices` vertices) as OBJ and returns its path.
pub fn small_roof(dir: &Scratch, vertices: usize) -> PathBuf {
    let mesh = hall_roof(vertices).into_mesh().expect("valid roof");
    let path = dir.path("roof.obj");
    mesh.write_obj(std::fs::File::create(&path).expect("create obj")).expect("write obj");
    path
}

/// Runs `lamella` with `args` in `cwd`.
pub fn lamella(cwd: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_lamella")).args(args).current_dir(cwd).output().expect("run lamella")
}

/// Runs `lamella` with `args` in `cwd` with a fixed number of worker threads.
pub fn lamella_threads(cwd: &Path, threads: usize, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_lamella"))
        .args(args)
        .current_dir(cwd)
        .env("RAYON_NUM_THREADS", threads.to_string())
        .output()
        .expect("run lamella")
}

/// Runs `args` in `dir`, checks exit code 2 with a single stderr line containing every
/// `needle`, and returns that line.
pub fn assert_bad_input(dir: &Path, args: &[&str], needles: &[&str]) -> String {
    let output = lamella(dir, args);
    let message = stderr(&output);
    assert_eq!(output.status.code(), Some(2), "{args:?}: {message}");
    assert_eq!(message.trim_end().lines().count(), 1, "{args:?}: one line, got {message}");
    for needle in needles {
        assert!(message.contains(needle), "{args:?}: `{needle}` not in {message}");
    }
    message
}

pub fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

pub fn stdout(output: &Output) -> String {
    String::from_utf8_lossy(&output.stdout).into_owned()
}

/// Asserts success, showing stderr otherwise.
pub fn assert_ok(output: &Output) {
    assert!(output.status.success(), "lamella failed ({:?}): {}", output.status.code(), stderr(output));
}

pub fn read_json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).expect("read json")).expect("valid JSON")
}

/// An element of a parsed XML document: name, attributes and children.
#[derive(Debug)]
pub struct Element {
    pub name: String,
    pub attributes: Vec<(String, String)>,
    pub children: Vec<Element>,
    pub text: String,
}

impl Element {
    pub fn attribute(&self, name: &str) -> Option<&str> {
        self.attributes.iter().find(|(k, _)| k == name).map(|(_, v)| v.as_str())
    }

    /// All descendants (depth first) named `name`.
    pub fn descendants<'a>(&'a self, name: &str, found: &mut Vec<&'a Element>) {
        for child in &self.children {
            if child.name == name {
                found.push(child);
            }
            child.descendants(name, found);
        }
    }
}

/// A strict little XML parser for the SVGs the CLI writes: one root element, balanced and
/// properly nested tags, quoted attributes without `<`, only the five predefined entities.
/// Panics with a message on malformed input.
pub fn parse_xml(text: &str) -> Element {
    let mut rest = text.trim_start();
    if rest.starts_with("<?xml") {
        let end = rest.find("?>").expect("unterminated XML declaration");
        rest = rest[end + 2..].trim_start();
    }
    let mut stack: Vec<Element> = vec![Element { name: String::new(), attributes: vec![], children: vec![], text: String::new() }];
    while !rest.is_empty() {
        if let Some(after) = rest.strip_prefix("</") {
            let end = after.find('>').expect("unterminated closing tag");
            let name = after[..end].trim();
            let element = stack.pop().expect("stack");
            assert_eq!(element.name, name, "closing tag </{name}> does not match <{}>", element.name);
            stack.last_mut().expect("closing the document node").children.push(element);
            rest = &after[end + 1..];
        } else if let Some(after) = rest.strip_prefix('<') {
            let end = after.find('>').expect("unterminated tag");
            let mut tag = &after[..end];
            let self_closing = tag.ends_with('/');
            if self_closing {
                tag = &tag[..tag.len() - 1];
            }
            let name_end = tag.find(char::is_whitespace).unwrap_or(tag.len());
            let name = tag[..name_end].to_string();
            assert!(!name.is_empty() && name.chars().all(|c| c.is_alphanumeric() || c == ':' || c == '-' || c == '_'), "bad tag name `{name}`");
            let attributes = parse_attributes(&tag[name_end..]);
            let element = Element { name, attributes, children: vec![], text: String::new() };
            if self_closing {
                stack.last_mut().expect("stack").children.push(element);
            } else {
                stack.push(element);
            }
            rest = &after[end + 1..];
        } else {
            let end = rest.find('<').unwrap_or(rest.len());
            let text = &rest[..end];
            check_entities(text);
            assert!(stack.len() > 1 || text.trim().is_empty(), "text outside the root element");
            stack.last_mut().expect("stack").text.push_str(text);
            rest = &rest[end..];
        }
    }
    assert_eq!(stack.len(), 1, "unclosed element <{}>", stack.last().map_or("", |e| e.name.as_str()));
    let mut document = stack.pop().expect("document");
    assert_eq!(document.children.len(), 1, "an XML document has exactly one root element");
    document.children.pop().expect("root")
}

fn check_entities(text: &str) {
    for (i, _) in text.match_indices('&') {
        let entity = &text[i..text[i..].find(';').map_or(text.len(), |e| i + e + 1)];
        assert!(["&amp;", "&lt;", "&gt;", "&quot;", "&apos;"].contains(&entity), "unknown entity `{entity}`");
    }
}

fn parse_attributes(mut text: &str) -> Vec<(String, String)> {
    let mut attributes = Vec::new();
    loop {
        text = text.trim_start();
        if text.is_empty() {
            return attributes;
        }
        let eq = text.find('=').expect("attribute without value");
        let name = text[..eq].trim().to_string();
        assert!(!name.is_empty() && !name.contains(char::is_whitespace), "bad attribute name `{name}`");
        let after = text[eq + 1..].trim_start();
        let quote = after.chars().next().expect("attribute value");
        assert!(quote == '"' || quote == '\'', "unquoted attribute `{name}`");
        let close = after[1..].find(quote).expect("unterminated attribute value") + 1;
        let value = &after[1..close];
        assert!(!value.contains('<'), "`<` in attribute `{name}`");
        check_entities(value);
        assert!(!attributes.iter().any(|(n, _)| n == &name), "repeated attribute `{name}`");
        attributes.push((name, value.to_string()));
        text = &after[close + 1..];
    }
}

/// Parses an SVG polygon's `points` attribute.
pub fn polygon_points(element: &Element) -> Vec<[f64; 2]> {
    element
        .attribute("points")
        .expect("points")
        .split_whitespace()
        .map(|pair| {
            let (x, y) = pair.split_once(',').expect("x,y");
            let p: [f64; 2] = [x.parse().expect("x"), y.parse().expect("y")];
            assert!(p.iter().all(|c| c.is_finite()), "non-finite point {pair}");
            p
        })
        .collect()
}

/// Checks an SVG file is well-formed XML with an `svg` root, and returns the root.
pub fn parse_svg(path: &Path) -> Element {
    let text = std::fs::read_to_string(path).expect("read svg");
    assert!(!text.contains("NaN"), "{}: NaN in the file", path.display());
    let root = parse_xml(&text);
    assert_eq!(root.name, "svg", "{}: root element", path.display());
    assert_eq!(root.attribute("xmlns"), Some("http://www.w3.org/2000/svg"));
    root
}
