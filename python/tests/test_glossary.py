"""The glossary of docs/math/conventions.md has a Python column, and it names only what the
package has: every `sb.NAME` and `Motion.NAME` in that column is an attribute of `screwbender`
or `screwbender.Motion`, so a rename that forgets the glossary fails here."""

import re

import screwbender as sb
from conftest import ROOT
from test_inputs import P

CONVENTIONS = ROOT / "docs" / "math" / "conventions.md"


def cells(line):
    """The cells of a Markdown table row (`\\|` is a literal bar inside a cell)."""
    parts = re.split(r"(?<!\\)\|", line.strip())
    return [p.strip().replace("\\|", "|") for p in parts[1:-1]]


def glossary():
    """`{term: python_cell}` of the glossary table."""
    lines = CONVENTIONS.read_text(encoding="utf-8").splitlines()
    start = lines.index("## 5. Glossary")
    header_at = next(i for i in range(start, len(lines)) if lines[i].startswith("| term |"))
    header = cells(lines[header_at])
    assert "Python" in header, "the glossary has no Python column"
    column = header.index("Python")
    rows = {}
    for line in lines[header_at + 2 :]:
        if not line.startswith("|"):
            break
        row = cells(line)
        assert len(row) == len(header), f"row {row[0]!r} has {len(row)} cells, not {len(header)}"
        rows[row[0]] = row[column]
    return rows


def named(cell):
    """The `(owner, attribute)` pairs of the `sb.X` / `Motion.X` code spans of a cell."""
    found = []
    for span in re.findall(r"`([^`]+)`", cell):
        m = re.match(r"(sb|Motion)\.(\w+)", span)
        if m:
            found.append((m.group(1), m.group(2)))
    return found


def test_every_python_name_of_the_glossary_exists():
    rows = glossary()
    assert len(rows) >= 15
    for term, cell in rows.items():
        if cell == "—":  # a concept with no name of its own (Split&Tweak, the framework)
            continue
        names = named(cell)
        assert names, f"{term}: the Python cell names nothing: {cell!r}"
        for owner, attribute in names:
            where = sb if owner == "sb" else sb.Motion
            assert hasattr(where, attribute), f"{term}: {owner}.{attribute} does not exist"


def test_the_glossarys_rule_set_ids_are_the_ones_python_reports():
    ids = re.findall(r'"(\w+)"', glossary()["rules"])
    assert ids == ["direct", "split"]
    for rules in ids:
        assert sb.Motion(P, rules=rules).rules == rules
