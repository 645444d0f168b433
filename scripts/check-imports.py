#!/usr/bin/env python3
"""No import circles between the source files of a crate, and no import from the crate root.

Reads every `.rs` file under each crate's `src/`, resolves its `use crate::…`, `use super::…`
and inline `crate::a::b::…` paths to the file of the module they name, and fails when the
files' import graph has a cycle (printing it). Declaring a child module (`mod x;`) is not an
import; re-exporting one (`pub use x::Y`) is. The crate root (`lib.rs`), which only declares
modules and re-exports them, is left out: every file may name items through it, as long as
files below it name the module an item lives in, not the root's re-export of it (an
import from a module above).

    scripts/check-imports.py [CRATE_DIR ...]   # default: every crates/*/
"""
import re
import sys
from pathlib import Path

USE = re.compile(r'\buse\s+((?:crate|super|self)(?:::[\w{}, :*]+)?)\s*;', re.S)
INLINE = re.compile(r'\b((?:crate|super)(?:::\w+)+)')


def modules(src):
    """Maps module paths (tuples) to files."""
    out = {}
    for f in src.rglob('*.rs'):
        rel = f.relative_to(src).with_suffix('')
        parts = list(rel.parts)
        if parts[-1] in ('mod', 'lib', 'main'):
            parts = parts[:-1]
        out[tuple(parts)] = f
    return out


def strip_comments(text):
    text = re.sub(r'//[^\n]*', '', text)
    return re.sub(r'/\*.*?\*/', '', text, flags=re.S)


def expand(path):
    """`a::{b, c::d}` → [`a::b`, `a::c::d`] (one level of braces is enough here)."""
    m = re.match(r'^(.*?)::\{(.*)\}$', path.replace('\n', ' ').replace(' ', ''), re.S)
    if not m:
        return [path.replace(' ', '')]
    head, body = m.groups()
    items, depth, cur = [], 0, ''
    for c in body:
        if c == ',' and depth == 0:
            items.append(cur)
            cur = ''
            continue
        depth += (c == '{') - (c == '}')
        cur += c
    items.append(cur)
    return [p for i in items if i for p in expand(f'{head}::{i}')]


def check(crate):
    src = crate / 'src'
    mods = modules(src)
    owner = {f: p for p, f in mods.items()}
    edges = {}
    root_imports = []
    for f, here in owner.items():
        if here == ():
            continue
        is_dir_mod = f.name == 'mod.rs'
        text = strip_comments(f.read_text())
        # `#[cfg(test)] mod tests { … }` is test code, which may import freely.
        text = re.split(r'#\[cfg\(test\)\]\s*(?:pub(?:\(crate\))?\s+)?mod tests', text)[0]
        paths = [p for m in USE.finditer(text) for p in expand(m.group(1))]
        paths += INLINE.findall(text)
        targets = set()
        for p in paths:
            parts = p.split('::')
            if parts[0] == 'crate':
                base, rest = [], parts[1:]
            else:
                # `super` of a mod.rs is its parent's parent module's file.
                base = list(here) if is_dir_mod else list(here)
                rest = parts
                while rest and rest[0] in ('super', 'self'):
                    if rest[0] == 'super':
                        base = base[:-1]
                    rest = rest[1:]
            # The longest module prefix that names a file.
            best = None
            for k in range(len(rest), -1, -1):
                key = tuple(base + rest[:k])
                if key in mods:
                    best = key
                    break
            if best == () and parts[0] == 'crate' and rest:
                root_imports.append(f'{f.relative_to(crate)}: {p}')
                continue
            if best is None or best == () or mods[best] == f:
                continue
            targets.add(mods[best])
        edges[f] = targets
    # Cycles by depth-first search.
    state, stack, cycles = {}, [], []

    def visit(f):
        state[f] = 1
        stack.append(f)
        for g in sorted(edges.get(f, ())):
            if state.get(g) == 1:
                cycles.append(stack[stack.index(g):] + [g])
            elif g not in state:
                visit(g)
        stack.pop()
        state[f] = 2

    for f in sorted(edges):
        if f not in state:
            visit(f)
    return cycles, sorted(set(root_imports))


def main():
    root = Path(__file__).resolve().parent.parent
    crates = [Path(a) for a in sys.argv[1:]] or sorted(p for p in (root / 'crates').iterdir() if (p / 'src').is_dir())
    bad = 0
    for crate in crates:
        cycles, root_imports = check(crate)
        for c in cycles:
            print(f'{crate.name}: import circle: ' + ' → '.join(str(f.relative_to(crate)) for f in c))
        for r in root_imports:
            print(f'{crate.name}: imports from the crate root (name the module instead): {r}')
        bad += len(cycles) + len(root_imports)
        if not cycles and not root_imports:
            print(f'{crate.name}: no import circles, nothing imported from the crate root')
    sys.exit(1 if bad else 0)


if __name__ == '__main__':
    main()
