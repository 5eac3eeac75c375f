#!/usr/bin/env python3
"""The house rules that a reader of the code can count, checked over the workspace.

1. No file under the engine's src/ exceeds 1,000 lines (tests included).
2. No Rust function exceeds 100 lines, unless a comment just above it (among its doc
   comments and attributes) says why, with the words "Long because".
3. No crate has an import circle between sibling modules: a file of module a names
   module b (`crate::b`, `super::b`) and a file of b names a, directly or through others.
4. Comments say what and why, never the history: no "issue N", no 'issue "title"' or
   "the issue's", and no commit hash
   ("commit 1a2b3c4", or a bare hash of 7 to 40 hex digits holding a letter and a digit)
   in the comments of Rust sources, build files and scripts. History goes in CHANGELOG.md.

Usage: scripts/check-structure.py [ROOT] [--report] | --canary
Exit 0 when every rule holds, 1 otherwise, listing each breach. --report also prints the
25 longest functions. --canary plants one breach of each rule in a temporary tree and
exits 1 unless each is reported.
"""

import os
import re
import sys

MAX_ENGINE_FILE_LINES = 1000
MAX_FUNCTION_LINES = 100
EXEMPTION = re.compile(r"long because", re.IGNORECASE)
SKIP_DIRS = {"target", ".git", "node_modules", "corpus", "artifacts"}
FN_HEAD = re.compile(
    r"^\s*(?:pub(?:\([^)]*\))?\s+)?(?:default\s+)?(?:const\s+)?(?:async\s+)?"
    r"(?:unsafe\s+)?(?:extern\s+\"[^\"]*\"\s+)?fn\s+([A-Za-z_][A-Za-z0-9_]*)"
)


def rust_files(root):
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames[:] = sorted(d for d in dirnames if d not in SKIP_DIRS and not d.startswith("."))
        for name in sorted(filenames):
            if name.endswith(".rs"):
                yield os.path.join(dirpath, name)


def strip_code(text):
    """The text with comments, strings and char literals blanked (newlines kept), so that
    braces and paths are counted in code only."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            depth, j = 1, i + 2
            while j < n and depth:
                if text.startswith("/*", j):
                    depth, j = depth + 1, j + 2
                elif text.startswith("*/", j):
                    depth, j = depth - 1, j + 2
                else:
                    j += 1
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == "r" and re.match(r'r#*"', text[i:i + 10]) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            hashes = re.match(r"r(#*)\"", text[i:]).group(1)
            end = text.find('"' + hashes, i + 2 + len(hashes))
            end = n if end < 0 else end + 1 + len(hashes)
            out.append(re.sub(r"[^\n]", " ", text[i:end]))
            i = end
        elif c == '"':
            j = i + 1
            while j < n and text[j] != '"':
                j += 2 if text[j] == "\\" else 1
            out.append(re.sub(r"[^\n]", " ", text[i:j + 1]))
            i = j + 1
        elif c == "'":
            m = re.match(r"'(?:\\.|\\u\{[0-9a-fA-F]+\}|[^\\'])'", text[i:i + 12])
            if m:
                out.append(" " * len(m.group(0)))
                i += len(m.group(0))
            else:  # a lifetime
                out.append(c)
                i += 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def functions(path):
    """(name, first line, line count, exempt) for each fn with a body in the file."""
    with open(path, encoding="utf-8") as f:
        raw = f.read()
    raw_lines = raw.split("\n")
    code = strip_code(raw)
    lines = code.split("\n")
    found = []
    for idx, line in enumerate(lines):
        m = FN_HEAD.match(line)
        if not m:
            continue
        # find the body's opening brace (or a ';' for a declaration without a body)
        depth, start, end = 0, None, None
        for j in range(idx, len(lines)):
            for ch in lines[j]:
                if start is None:
                    if ch == ";" and depth == 0:
                        start = -1
                        break
                    if ch in "([<":
                        depth += 1
                    elif ch in ")]>":
                        depth -= 1
                    elif ch == "{":
                        start, depth = j, 1
                else:
                    if ch == "{":
                        depth += 1
                    elif ch == "}":
                        depth -= 1
                        if depth == 0:
                            end = j
                            break
            if start == -1 or end is not None:
                break
        if start in (None, -1) or end is None:
            continue
        # the comments and attributes just above the fn
        k, above = idx - 1, []
        while k >= 0 and re.match(r"^\s*(//|#\[|#!\[)", raw_lines[k]):
            above.append(raw_lines[k])
            k -= 1
        found.append((m.group(1), idx + 1, end - idx + 1, any(EXEMPTION.search(a) for a in above)))
    return found


HISTORY = re.compile(r"\bissue\s+(#?\d+|\")|\bthe issue's\b|\bcommit\s+[0-9a-f]{7,40}\b", re.IGNORECASE)
HASH = re.compile(r"\b(?=[0-9a-f]*[a-f])(?=[0-9a-f]*[0-9])[0-9a-f]{7,40}\b")
HISTORY_FILES = (".rs", ".toml", ".sh", ".py")
HISTORY_NAMES = ("run", "build.sh")


def comments(path):
    """(line number, comment text) for each comment line of a Rust, TOML, shell or Python
    file (`//` and `#` comments; a `#` inside a string is not told apart, which errs on the
    side of reporting)."""
    marker = "//" if path.endswith(".rs") else "#"
    with open(path, encoding="utf-8") as f:
        for k, line in enumerate(f, 1):
            at = line.find(marker)
            if at >= 0 and not (marker == "#" and line.lstrip().startswith("#!") and k == 1):
                if marker == "#" and path.endswith(".rs"):
                    continue
                yield k, line[at:]


def history_files(root):
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames[:] = sorted(d for d in dirnames if d not in SKIP_DIRS and (not d.startswith(".") or d in (".ci", ".clusterfuzzlite")))
        for name in sorted(filenames):
            if name.endswith(HISTORY_FILES) or name in HISTORY_NAMES:
                yield os.path.join(dirpath, name)


def crate_roots(root):
    """Every src/ folder of a crate in the workspace (a folder holding Cargo.toml and src/)."""
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames[:] = [d for d in dirnames if d not in SKIP_DIRS and not d.startswith(".")]
        if "Cargo.toml" in filenames and os.path.isdir(os.path.join(dirpath, "src")):
            yield os.path.join(dirpath, "src")


def module_path(src, path):
    """The module path of a file: src/a/b.rs and src/a/b/mod.rs are ("a", "b")."""
    parts = os.path.relpath(path, src)[:-3].split(os.sep)
    if parts[-1] in ("mod", "lib", "main"):
        parts = parts[:-1]
    if parts and parts[0] == "bin":
        return None
    return tuple(parts)


def references(code, here):
    """The module paths a file's code names: `crate::a::b`, `super::a`, and the members of
    `use crate::{…}` / `use super::{…}` groups, each as a tuple of names."""
    found = []
    for m in re.finditer(r"\b(crate|super)((?:::[a-z_][a-z0-9_]*)*)(::\{([^}]*)\})?", code):
        base = () if m.group(1) == "crate" else here[:-1]
        path = base + tuple(x for x in m.group(2).split("::") if x)
        found.append(path)
        if m.group(4):
            for item in re.findall(r"(?:^|,)\s*([a-z_][a-z0-9_]*(?:::[a-z_][a-z0-9_]*)*)", m.group(4)):
                found.append(path + tuple(item.split("::")))
    return found


def module_graph(src):
    """For every pair of sibling modules a and b (children of one parent), an edge a -> b
    when a file inside a names a module inside b. A module and its own children are not
    compared: a parent that declares a child and a child that uses its parent is Rust's
    ordinary shape. Nodes are "parent::child" strings."""
    files = {}
    for path in rust_files(src):
        mp = module_path(src, path)
        if mp is not None:
            files[path] = mp
    known = set(files.values())
    graph = {}
    for path, here in files.items():
        with open(path, encoding="utf-8") as f:
            code = strip_code(f.read())
        for ref in references(code, here):
            while ref and ref not in known:
                ref = ref[:-1]
            if not ref:
                continue
            k = 0
            while k < min(len(here), len(ref)) and here[k] == ref[k]:
                k += 1
            if k == len(here) or k == len(ref):
                continue  # one contains the other
            a, b = "::".join(here[:k + 1]), "::".join(ref[:k + 1])
            graph.setdefault(a, set()).add(b)
            graph.setdefault(b, set())
    return graph


def circles(graph):
    """The strongly connected components with more than one module (Tarjan)."""
    index, low, stack, on, out = {}, {}, [], set(), []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in graph:
                continue
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


def check(root, report=False):
    """Every breach of the four rules in the tree at root, as lines to print."""
    breaches = []

    engine_src = os.path.join(root, "src")
    for path in rust_files(engine_src):
        with open(path, encoding="utf-8") as f:
            count = f.read().count("\n")
        if count > MAX_ENGINE_FILE_LINES:
            breaches.append(f"{os.path.relpath(path, root)}: {count} lines (at most {MAX_ENGINE_FILE_LINES} in the engine's src/)")

    longest = []
    for path in rust_files(root):
        for name, line, count, exempt in functions(path):
            longest.append((count, f"{os.path.relpath(path, root)}:{line} fn {name}", exempt))
            if count > MAX_FUNCTION_LINES and not exempt:
                breaches.append(f"{os.path.relpath(path, root)}:{line}: fn {name} has {count} lines (at most {MAX_FUNCTION_LINES}, or a comment above it saying 'Long because ...')")

    for src in sorted(crate_roots(root)):
        for comp in circles(module_graph(src)):
            breaches.append(f"{os.path.relpath(src, root)}: import circle between the modules {', '.join(comp)}")

    for path in history_files(root):
        if os.path.basename(path) == "check-structure.py":
            continue
        for k, text in comments(path):
            m = HISTORY.search(text) or HASH.search(text)
            if m:
                breaches.append(f"{os.path.relpath(path, root)}:{k}: history in a comment ({m.group(0)!r}); it belongs in CHANGELOG.md")

    if report:
        for count, where, exempt in sorted(longest, reverse=True)[:25]:
            print(f"{count:5} {where}{' (exempt)' if exempt else ''}")
    return breaches


def canary():
    """The checks must see: a tree planted with one breach of each rule (and an exempt long
    function, which must pass) gets exactly those breaches."""
    import tempfile

    long_body = "".join(f"    let x{k} = {k};\n" for k in range(101))
    files = {
        "Cargo.toml": "[package]\nname = \"canary\"\n",
        "src/lib.rs": "mod a;\nmod b;\n",
        "src/a.rs": "use crate::b::g;\n/// A.\npub fn f() {\n" + long_body + "}\n",
        "src/b.rs": "// fixed in issue 42\npub fn g() -> u8 {\n    crate::a::f();\n    1\n}\n"
        "/// Long because a table of cases reads best whole.\nfn h() {\n" + long_body + "}\n",
        "src/big.rs": "// filler\n" * (MAX_ENGINE_FILE_LINES + 1),
    }
    with tempfile.TemporaryDirectory() as tmp:
        for rel, text in files.items():
            path = os.path.join(tmp, rel)
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, "w", encoding="utf-8") as f:
                f.write(text)
        found = check(tmp)
    want = [
        ("src/big.rs", "lines (at most"),
        ("src/a.rs", "fn f has 103 lines"),
        ("src/b.rs", "history in a comment ('issue 42')"),
        ("src", "import circle between the modules a, b"),
    ]
    missing = [w for w in want if not any(w[0] in b and w[1] in b for b in found)]
    extra = [b for b in found if not any(w[0] in b and w[1] in b for w in want)]
    for w in missing:
        print(f"canary: the planted breach {w} was not reported")
    for b in extra:
        print(f"canary: reported more than was planted: {b}")
    print(f"check-structure canary: {len(want) - len(missing)} of {len(want)} planted breaches reported")
    return 1 if missing or extra else 0


def main(argv):
    if "--canary" in argv:
        return canary()
    args = [a for a in argv if not a.startswith("--")]
    root = os.path.abspath(args[0] if args else os.path.join(os.path.dirname(__file__), ".."))
    breaches = check(root, report="--report" in argv)
    for b in breaches:
        print(b)
    print(f"check-structure: {len(breaches)} breaches")
    return 1 if breaches else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
