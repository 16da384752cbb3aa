//! The house's import rules (ARCHITECTURE.md, "Who imports whom"), checked
//! from the source: every `use` and every `crate::`/`super::`/`self::` path
//! in `src/` is read, resolved to the file that defines what it names, and
//! held to four rules:
//!
//! 1. the top-level folders import only from stages to their left;
//! 2. no import circle between the files (or sub-folders) of one folder;
//! 3. a `mod.rs` is a map: at most 150 lines, no item defined in it;
//! 4. a file imports its siblings' items from their files, never through its
//!    own folder's `mod.rs` re-exports (an arrow back up).
//!
//! `deadline.rs` and `stop.rs` import nothing but each other.
//!
//! Code under `#[cfg(test)]` (a test module at the end of a file, or a file
//! declared `#[cfg(test)] mod NAME;`) is not held to them: unit tests may
//! compare production with the reference.
//!
//! Each rule's test first checks that the reader catches a planted
//! violation, so that a reader that sees nothing cannot pass.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// The stages, left to right: a top-level module may import only modules
/// earlier in this list (and `deadline`, `stop`, which import nothing).
const STAGES: &[&str] = &[
    "scene",
    "plan",
    "frame",
    "rasterizer",
    "reference",
    "production",
    "adapters",
    "metrics",
    "harness",
    "report",
    "registry",
    "explore",
    "bench",
    "commands",
];

/// Stages of one rank: neither may import the other.
const SIBLING_STAGES: &[&[&str]] = &[&["reference", "production", "adapters"]];

/// Arrows the order alone would allow but the house forbids: the metrics
/// read the reference's exact answers, never production's; the harness
/// judges what it is handed, and names no rasterizer (the registry does).
const FORBIDDEN: &[(&str, &str)] = &[
    ("metrics", "production"),
    ("harness", "production"),
    ("harness", "adapters"),
];

/// Used from every stage; they import nothing from the crate but each
/// other (a deadline's unwinding stops at a signal's flag).
const LEAVES: &[&str] = &["deadline", "stop"];

/// One source file as a module: its path in the crate and its code with
/// comments, strings and test-only parts removed.
struct Module {
    path: Vec<String>,
    file: PathBuf,
    is_mod_rs: bool,
    code: String,
    lines: usize,
}

/// Every module under `src/`, by module path (`["production", "method"]`).
fn read_crate(src: &Path) -> BTreeMap<Vec<String>, Module> {
    let mut files = Vec::new();
    collect(src, &mut files);
    let mut modules = BTreeMap::new();
    let mut test_only: BTreeSet<Vec<String>> = BTreeSet::new();
    for file in files {
        let rel = file.strip_prefix(src).unwrap();
        let mut path: Vec<String> = rel
            .with_extension("")
            .components()
            .map(|c| c.as_os_str().to_string_lossy().into_owned())
            .collect();
        let is_mod_rs = path.last().is_some_and(|l| l == "mod");
        if is_mod_rs || path == ["lib"] || path == ["main"] {
            path.pop();
        }
        if rel == Path::new("main.rs") {
            continue; // the binary: argument parsing on top of everything
        }
        let text = std::fs::read_to_string(&file).unwrap();
        let (code, tests) = strip(&text);
        for child in tests {
            let mut p = path.clone();
            p.push(child);
            test_only.insert(p);
        }
        modules.insert(
            path.clone(),
            Module {
                path,
                file,
                is_mod_rs,
                lines: text.lines().count(),
                code,
            },
        );
    }
    // Files declared `#[cfg(test)] mod NAME;`, and everything below them.
    modules.retain(|p, _| !test_only.iter().any(|t| p.starts_with(t)));
    modules
}

fn collect(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            collect(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The code of a file without comments, string and char literals, and
/// without its test-only part: everything from a `#[cfg(test)]` at the
/// start of a line that opens an inline module. Also returns the names of
/// modules declared test-only (`#[cfg(test)] mod NAME;`).
fn strip(text: &str) -> (String, Vec<String>) {
    let mut out = String::with_capacity(text.len());
    let bytes: Vec<char> = text.chars().collect();
    let mut i = 0;
    while i < bytes.len() {
        let c = bytes[i];
        let next = bytes.get(i + 1).copied();
        if c == '/' && next == Some('/') {
            while i < bytes.len() && bytes[i] != '\n' {
                i += 1;
            }
        } else if c == '/' && next == Some('*') {
            let mut depth = 0;
            while i < bytes.len() {
                if bytes[i] == '/' && bytes.get(i + 1) == Some(&'*') {
                    depth += 1;
                    i += 2;
                } else if bytes[i] == '*' && bytes.get(i + 1) == Some(&'/') {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    if bytes[i] == '\n' {
                        out.push('\n');
                    }
                    i += 1;
                }
            }
        } else if c == 'r' && (next == Some('"') || next == Some('#')) && is_raw_start(&bytes, i) {
            // r"..." or r#"..."#
            let mut j = i + 1;
            let mut hashes = 0;
            while bytes[j] == '#' {
                hashes += 1;
                j += 1;
            }
            j += 1; // the quote
            loop {
                if j >= bytes.len() {
                    break;
                }
                if bytes[j] == '"' && (0..hashes).all(|h| bytes.get(j + 1 + h) == Some(&'#')) {
                    j += 1 + hashes;
                    break;
                }
                if bytes[j] == '\n' {
                    out.push('\n');
                }
                j += 1;
            }
            out.push_str("\"\"");
            i = j;
        } else if c == '"' {
            i += 1;
            while i < bytes.len() && bytes[i] != '"' {
                if bytes[i] == '\\' {
                    i += 1;
                }
                if bytes.get(i) == Some(&'\n') {
                    out.push('\n');
                }
                i += 1;
            }
            i += 1;
            out.push_str("\"\"");
        } else if c == '\'' && is_char_literal(&bytes, i) {
            // 'x', '\n', '\u{..}'; a lifetime ('a) is left alone
            i += 1;
            while i < bytes.len() && bytes[i] != '\'' {
                if bytes[i] == '\\' {
                    i += 1;
                }
                i += 1;
            }
            i += 1;
            out.push_str("' '");
        } else {
            out.push(c);
            i += 1;
        }
    }
    // The test-only tail, and test-only child files.
    let mut kept = String::new();
    let mut tests = Vec::new();
    let mut lines = out.lines().peekable();
    while let Some(line) = lines.next() {
        if line.trim_start().starts_with("#[cfg(test)]") && !line.starts_with(' ') {
            // The item it guards: `mod NAME;` (a file) or `mod NAME {` (inline).
            let mut item = String::new();
            while let Some(next) = lines.peek() {
                if next.trim_start().starts_with("#[") || next.trim().is_empty() {
                    lines.next();
                    continue;
                }
                item = next.trim().to_owned();
                break;
            }
            let decl = item
                .trim_start_matches("pub ")
                .trim_start_matches("pub(crate) ");
            if let Some(rest) = decl.strip_prefix("mod ") {
                if let Some(name) = rest.strip_suffix(';') {
                    tests.push(name.trim().to_owned());
                    lines.next();
                    continue;
                }
                break; // an inline test module: the rest of the file
            }
            lines.next(); // a single test-only item (a use, a fn): dropped
            continue;
        }
        kept.push_str(line);
        kept.push('\n');
    }
    (kept, tests)
}

fn is_raw_start(bytes: &[char], i: usize) -> bool {
    let before = i.checked_sub(1).map(|b| bytes[b]);
    if before.is_some_and(|b| b.is_alphanumeric() || b == '_') {
        return false;
    }
    let mut j = i + 1;
    while j < bytes.len() && bytes[j] == '#' {
        j += 1;
    }
    bytes.get(j) == Some(&'"')
}

fn is_char_literal(bytes: &[char], i: usize) -> bool {
    matches!(
        (bytes.get(i + 1), bytes.get(i + 2)),
        (Some('\\'), _) | (Some(_), Some('\''))
    )
}

/// Every path a module's code names from `crate`, `super` or `self`, made
/// absolute (`["harness", "suite", "run_candidate"]`): `use` trees
/// expanded, inline paths as written.
fn named_paths(module: &Module) -> Vec<Vec<String>> {
    let mut paths = Vec::new();
    let code = &module.code;
    // `use` declarations (possibly over several lines), expanded.
    let mut rest = code.as_str();
    let mut without_uses = String::new();
    while let Some(at) = find_use(rest) {
        without_uses.push_str(&rest[..at]);
        let after = &rest[at..];
        let start = after.find("use ").unwrap() + 4;
        let end = after[start..].find(';').map_or(after.len(), |e| start + e);
        for path in expand(&squeeze(&after[start..end])) {
            paths.push(path);
        }
        rest = &after[(end + 1).min(after.len())..];
    }
    without_uses.push_str(rest);
    // Inline paths: crate::a::b, super::x, self::y.
    let chars: Vec<char> = without_uses.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        let boundary = i == 0 || !(chars[i - 1].is_alphanumeric() || chars[i - 1] == '_');
        if boundary {
            for head in ["crate::", "super::", "self::"] {
                if starts_with(&chars, i, head) {
                    let mut j = i;
                    while j < chars.len()
                        && (chars[j].is_alphanumeric() || chars[j] == '_' || chars[j] == ':')
                    {
                        j += 1;
                    }
                    let text: String = chars[i..j].iter().collect();
                    let segments: Vec<String> = text
                        .split("::")
                        .filter(|s| !s.is_empty())
                        .map(str::to_owned)
                        .collect();
                    paths.push(segments);
                    i = j;
                    break;
                }
            }
        }
        i += 1;
    }
    paths
        .into_iter()
        .filter_map(|p| absolute(&module.path, &p))
        .collect()
}

fn starts_with(chars: &[char], i: usize, s: &str) -> bool {
    s.chars()
        .enumerate()
        .all(|(k, c)| chars.get(i + k) == Some(&c))
}

/// The offset of the next `use` declaration (`use`, `pub use`,
/// `pub(crate) use` at the start of a statement).
fn find_use(code: &str) -> Option<usize> {
    let mut from = 0;
    while let Some(at) = code[from..].find("use ") {
        let at = from + at;
        let before = code[..at].trim_end();
        let ok = before.is_empty()
            || before.ends_with(';')
            || before.ends_with('{')
            || before.ends_with('}')
            || before.ends_with(']')
            || before.ends_with("pub")
            || before.ends_with(')') && before.ends_with("pub(crate)")
            || before.ends_with("pub(super)");
        let word_start =
            at == 0 || !code[..at].ends_with(|c: char| c.is_alphanumeric() || c == '_');
        if ok && word_start {
            return Some(at);
        }
        from = at + 4;
    }
    None
}

/// A `use` tree without white space but around `as` (`a::{b as c,d}`).
fn squeeze(tree: &str) -> String {
    tree.split_whitespace()
        .map(|t| if t == "as" { " as " } else { t })
        .collect()
}

/// A `use` tree without white space (`crate::a::{b::{C,D},e}`) as paths.
fn expand(tree: &str) -> Vec<Vec<String>> {
    fn go(prefix: &[String], tree: &str, out: &mut Vec<Vec<String>>) {
        let tree = tree.trim_matches(',');
        if tree.is_empty() {
            return;
        }
        if let Some(open) = tree.find('{') {
            let head = &tree[..open];
            let inner = &tree[open + 1..tree.rfind('}').unwrap_or(tree.len())];
            let mut p = prefix.to_vec();
            p.extend(
                head.split("::")
                    .filter(|s| !s.is_empty())
                    .map(str::to_owned),
            );
            for part in split_top(inner) {
                go(&p, part, out);
            }
        } else {
            let mut p = prefix.to_vec();
            let name = tree.split(" as ").next().unwrap();
            p.extend(
                name.split("::")
                    .filter(|s| !s.is_empty())
                    .map(str::to_owned),
            );
            if p.last().is_some_and(|l| l == "self") {
                p.pop();
            }
            out.push(p);
        }
    }
    let mut out = Vec::new();
    go(&[], tree, &mut out);
    out
}

/// The parts of a brace group's inside, split at top-level commas.
fn split_top(s: &str) -> Vec<&str> {
    let mut parts = Vec::new();
    let (mut depth, mut start) = (0, 0);
    for (i, c) in s.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                parts.push(&s[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    parts.push(&s[start..]);
    parts
}

/// A path as written in module `here`, made absolute from the crate root;
/// `None` for paths into other crates.
fn absolute(here: &[String], path: &[String]) -> Option<Vec<String>> {
    let mut segments = path.iter();
    let mut base: Vec<String> = match segments.next()?.as_str() {
        "crate" => Vec::new(),
        "self" => here.to_vec(),
        "super" => here[..here.len().checked_sub(1)?].to_vec(),
        _ => return None,
    };
    let mut rest: Vec<String> = segments.cloned().collect();
    while rest.first().is_some_and(|s| s == "super") {
        rest.remove(0);
        base.pop();
    }
    base.extend(rest);
    Some(base)
}

/// Re-exports of a module: name → the absolute path it stands for.
fn reexports(module: &Module) -> BTreeMap<String, Vec<String>> {
    let mut map = BTreeMap::new();
    let code = &module.code;
    let mut from = 0;
    while let Some(at) = code[from..].find("pub use ") {
        let at = from + at;
        let start = at + "pub use ".len();
        let end = code[start..].find(';').map_or(code.len(), |e| start + e);
        for path in expand(&squeeze(&code[start..end])) {
            let absolute_path = if matches!(path[0].as_str(), "crate" | "self" | "super") {
                absolute(&module.path, &path)
            } else {
                // `pub use child::X` is relative to this module.
                let mut p = module.path.clone();
                p.extend(path.iter().cloned());
                Some(p)
            };
            if let (Some(p), Some(name)) = (absolute_path, path.last()) {
                if name != "*" {
                    map.insert(name.clone(), p);
                }
            }
        }
        from = end;
    }
    map
}

/// The module a path names, and whether it reached an item through a
/// module's re-export (the module that re-exported it).
struct Resolved {
    target: Vec<String>,
    via_reexport_of: Option<Vec<String>>,
}

fn resolve(
    modules: &BTreeMap<Vec<String>, Module>,
    exports: &BTreeMap<Vec<String>, BTreeMap<String, Vec<String>>>,
    path: &[String],
) -> Option<Resolved> {
    let mut via = None;
    let mut path = path.to_vec();
    for _ in 0..8 {
        // The longest prefix that is a module.
        let n = (0..=path.len())
            .rev()
            .find(|&n| modules.contains_key(&path[..n]))?;
        let module = path[..n].to_vec();
        if n == path.len() {
            return Some(Resolved {
                target: module,
                via_reexport_of: via,
            });
        }
        // An item of that module: defined there, or re-exported.
        match exports.get(&module).and_then(|e| e.get(&path[n])) {
            Some(real) if real[..] != path[..n + 1] => {
                via.get_or_insert_with(|| module.clone());
                let mut next = real.clone();
                next.extend(path[n + 1..].iter().cloned());
                path = next;
            }
            _ => {
                return Some(Resolved {
                    target: module,
                    via_reexport_of: via,
                })
            }
        }
    }
    None
}

/// Each module's outgoing references, resolved.
fn edges(modules: &BTreeMap<Vec<String>, Module>) -> Vec<(Vec<String>, Resolved)> {
    let exports: BTreeMap<_, _> = modules
        .iter()
        .map(|(p, m)| (p.clone(), reexports(m)))
        .collect();
    let mut out = Vec::new();
    for module in modules.values() {
        for path in named_paths(module) {
            if let Some(resolved) = resolve(modules, &exports, &path) {
                if resolved.target != module.path {
                    out.push((module.path.clone(), resolved));
                }
            }
        }
    }
    out
}

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

fn show(path: &[String]) -> String {
    if path.is_empty() {
        "crate".to_owned()
    } else {
        path.join("::")
    }
}

/// Rule 1: stage order between top-level modules.
fn stage_violations(modules: &BTreeMap<Vec<String>, Module>) -> Vec<String> {
    let rank = |name: &str| STAGES.iter().position(|s| *s == name);
    let mut found = BTreeSet::new();
    for (from, to) in edges(modules) {
        let (Some(a), Some(b)) = (from.first(), to.target.first()) else {
            continue;
        };
        if a == b {
            continue;
        }
        if LEAVES.contains(&a.as_str()) && !LEAVES.contains(&b.as_str()) {
            found.insert(format!(
                "{a} imports {} (it imports nothing but the other leaves)",
                show(&to.target)
            ));
            continue;
        }
        if LEAVES.contains(&b.as_str()) {
            continue;
        }
        let siblings = SIBLING_STAGES
            .iter()
            .any(|group| group.contains(&a.as_str()) && group.contains(&b.as_str()));
        let forbidden = FORBIDDEN.contains(&(a.as_str(), b.as_str()));
        let ok = match (rank(a), rank(b)) {
            (Some(x), Some(y)) => y < x && !siblings && !forbidden,
            _ => true, // lib.rs and modules outside the stages
        };
        if !ok {
            found.insert(format!(
                "{} ({}) imports {}: `{b}` is not a stage to the left of `{a}`",
                show(&from),
                modules[&from].file.display(),
                show(&to.target)
            ));
        }
    }
    found.into_iter().collect()
}

/// Rule 2: import circles between the children of one folder.
fn circles(modules: &BTreeMap<Vec<String>, Module>) -> Vec<String> {
    // folder → child → children it uses
    let mut graph: BTreeMap<Vec<String>, BTreeMap<String, BTreeSet<String>>> = BTreeMap::new();
    for (from, to) in edges(modules) {
        // The deepest common folder of the two, and the child of it each lies in.
        let common = from
            .iter()
            .zip(&to.target)
            .take_while(|(a, b)| a == b)
            .count();
        if common >= from.len() || common >= to.target.len() {
            continue; // one is inside the other (a folder and its own map)
        }
        let folder = from[..common].to_vec();
        graph
            .entry(folder)
            .or_default()
            .entry(from[common].clone())
            .or_default()
            .insert(to.target[common].clone());
    }
    let mut found = Vec::new();
    for (folder, children) in &graph {
        for component in strongly_connected(children) {
            if component.len() > 1 {
                found.push(format!(
                    "in {}: {} import each other",
                    show(folder),
                    component.into_iter().collect::<Vec<_>>().join(" ↔ ")
                ));
            }
        }
    }
    found
}

/// Tarjan's strongly connected components.
fn strongly_connected(graph: &BTreeMap<String, BTreeSet<String>>) -> Vec<BTreeSet<String>> {
    struct State<'a> {
        graph: &'a BTreeMap<String, BTreeSet<String>>,
        index: BTreeMap<&'a str, usize>,
        low: BTreeMap<&'a str, usize>,
        stack: Vec<&'a str>,
        on_stack: BTreeSet<&'a str>,
        out: Vec<BTreeSet<String>>,
    }
    fn visit<'a>(s: &mut State<'a>, v: &'a str) {
        let i = s.index.len();
        s.index.insert(v, i);
        s.low.insert(v, i);
        s.stack.push(v);
        s.on_stack.insert(v);
        if let Some(next) = s.graph.get(v) {
            for w in next {
                let w = w.as_str();
                if !s.index.contains_key(w) {
                    visit(s, w);
                    let low = s.low[v].min(s.low[w]);
                    s.low.insert(v, low);
                } else if s.on_stack.contains(w) {
                    let low = s.low[v].min(s.index[w]);
                    s.low.insert(v, low);
                }
            }
        }
        if s.low[v] == s.index[v] {
            let mut component = BTreeSet::new();
            while let Some(w) = s.stack.pop() {
                s.on_stack.remove(w);
                component.insert(w.to_owned());
                if w == v {
                    break;
                }
            }
            s.out.push(component);
        }
    }
    let mut s = State {
        graph,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on_stack: BTreeSet::new(),
        out: Vec::new(),
    };
    for v in graph.keys() {
        if !s.index.contains_key(v.as_str()) {
            visit(&mut s, v);
        }
    }
    s.out
}

/// Rule 3: a `mod.rs` is a map.
fn fat_maps(modules: &BTreeMap<Vec<String>, Module>) -> Vec<String> {
    const ITEMS: &[&str] = &[
        "fn ",
        "struct ",
        "enum ",
        "trait ",
        "impl ",
        "impl<",
        "type ",
        "const ",
        "static ",
        "union ",
        "macro_rules!",
    ];
    let mut found = Vec::new();
    for m in modules.values().filter(|m| m.is_mod_rs) {
        if m.lines > 150 {
            found.push(format!(
                "{}: {} lines (at most 150)",
                m.file.display(),
                m.lines
            ));
        }
        for (n, line) in m.code.lines().enumerate() {
            let mut item = line.trim_start();
            if line.starts_with(' ') || line.starts_with('\t') {
                continue; // inside a body: only items at the top count
            }
            for prefix in [
                "pub(crate) ",
                "pub(super) ",
                "pub ",
                "unsafe ",
                "async ",
                "const fn",
            ] {
                if prefix == "const fn" && item.starts_with(prefix) {
                    break;
                }
                item = item.strip_prefix(prefix).unwrap_or(item);
            }
            if let Some(kind) = ITEMS.iter().find(|k| item.starts_with(**k)) {
                found.push(format!(
                    "{}:{}: defines an item (`{}`): a mod.rs only declares, documents and re-exports",
                    m.file.display(),
                    n + 1,
                    kind.trim()
                ));
            }
        }
    }
    found
}

/// Rule 4: arrows back up through a folder's own re-exports.
fn climbs(modules: &BTreeMap<Vec<String>, Module>) -> Vec<String> {
    let mut found = BTreeSet::new();
    for (from, to) in edges(modules) {
        let Some(via) = &to.via_reexport_of else {
            continue;
        };
        // Through its own folder's map (or an ancestor's) to something
        // inside that folder: it should name the file.
        if from.starts_with(via) && from.len() > via.len() && to.target.starts_with(via) {
            found.insert(format!(
                "{} ({}) reaches {} through the re-exports of {}: import it from its file",
                show(&from),
                modules[&from].file.display(),
                show(&to.target),
                show(via)
            ));
        }
    }
    found.into_iter().collect()
}

fn assert_none(rule: &str, found: Vec<String>) {
    assert!(
        found.is_empty(),
        "{rule}: {} violation(s):\n  {}",
        found.len(),
        found.join("\n  ")
    );
}

/// A crate written in a temporary folder, for the planted violations.
fn planted(files: &[(&str, &str)]) -> BTreeMap<Vec<String>, Module> {
    let dir = std::env::temp_dir().join(format!(
        "rastercheck-architecture-{}-{}",
        std::process::id(),
        files.len()
            + files
                .iter()
                .map(|(p, c)| p.len() * 31 + c.len())
                .sum::<usize>()
    ));
    let _ = std::fs::remove_dir_all(&dir);
    for (path, code) in files {
        let file = dir.join(path);
        std::fs::create_dir_all(file.parent().unwrap()).unwrap();
        std::fs::write(file, code).unwrap();
    }
    let modules = read_crate(&dir);
    let _ = std::fs::remove_dir_all(&dir);
    modules
}

#[test]
fn stages_import_only_from_their_left() {
    let planted = planted(&[
        ("lib.rs", "pub mod metrics;\npub mod production;\npub mod scene;\n"),
        ("metrics/mod.rs", "//! m\nmod judge;\n"),
        (
            "metrics/judge.rs",
            "use crate::production::{fast::Fast, other};\nuse crate::scene::Scene;\n",
        ),
        ("production/mod.rs", "pub mod fast;\npub mod other;\n"),
        ("production/fast.rs", "pub struct Fast;\n"),
        ("production/other.rs", "// crate::metrics::judge in a comment\nfn f() { let _ = \"crate::metrics::x\"; crate::scene::g(); }\n"),
        ("scene/mod.rs", "pub struct Scene;\n"),
    ]);
    let found = stage_violations(&planted);
    assert_eq!(
        found.len(),
        2,
        "the reader must see both arrows: {found:#?}"
    );
    assert!(found.iter().all(|f| f.starts_with("metrics::judge")));
    assert_none("stage order", stage_violations(&read_crate(&src())));
}

#[test]
fn no_import_circles_inside_a_folder() {
    let planted = planted(&[
        ("lib.rs", "pub mod gl;\n"),
        ("gl/mod.rs", "mod context;\nmod depth;\nmod draw;\npub use draw::Draw;\n"),
        ("gl/context.rs", "use super::depth::Depth;\npub struct Context;\n"),
        ("gl/depth.rs", "pub struct Depth(super::Draw);\n"),
        (
            "gl/draw.rs",
            "pub struct Draw(crate::gl::context::Context);\n#[cfg(test)]\nmod tests { use super::super::depth::Depth; }\n",
        ),
    ]);
    let found = circles(&planted);
    assert_eq!(
        found,
        ["in gl: context ↔ depth ↔ draw import each other"],
        "a circle through a re-export must be seen"
    );
    assert_none("import circles", circles(&read_crate(&src())));
}

#[test]
fn a_mod_rs_is_a_map() {
    let long = format!("//! map\n{}pub use a::A;\n", "mod a;\n".repeat(151));
    let planted = planted(&[
        ("lib.rs", "pub mod x;\npub mod y;\n"),
        (
            "x/mod.rs",
            "//! x\nmod a;\npub fn helper() {}\n#[cfg(test)]\nmod tests {\n    fn t() {}\n}\n",
        ),
        ("x/a.rs", "pub struct A;\n"),
        ("y/mod.rs", long.as_str()),
        ("y/a.rs", "pub struct A;\n"),
    ]);
    let found = fat_maps(&planted);
    assert_eq!(found.len(), 2, "{found:#?}");
    assert_none("mod.rs files", fat_maps(&read_crate(&src())));
}

#[test]
fn no_climbs_back_up_through_a_map() {
    let planted = planted(&[
        ("lib.rs", "pub mod p;\npub mod q;\n"),
        (
            "p/mod.rs",
            "mod alias;\nmod method;\nmod triangle;\npub use alias::Alias as Method2;\npub use method::Method;\n",
        ),
        ("p/method.rs", "pub struct Method;\n"),
        ("p/alias.rs", "pub struct Alias;\n"),
        (
            "p/triangle.rs",
            "use super::Method;\nuse super::method::Method as M;\nuse super::alias;\n",
        ),
        ("q/mod.rs", "mod r;\n"),
        ("q/r.rs", "use crate::p::Method;\n"),
    ]);
    let found = climbs(&planted);
    assert_eq!(found.len(), 1, "only p::triangle climbs: {found:#?}");
    assert_none("climbs", climbs(&read_crate(&src())));
}
