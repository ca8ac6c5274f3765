#!/usr/bin/env python3
"""Checks docs/benchmarks.md against the outputs bench/run.sh leaves in build/bench/results/.

A page row is checked when it gives a verdict and its benchmark output can be found:
  - the verdict: "yes" or "no" in a "met" column, or "caught" / "fell" in one of its cells;
  - the output: either a row of a benchmark's printed markdown table (results/<name>.txt, the
    stdout bench/run.sh tees there) whose first cell is the page row's first cell, character for
    character (e.g. "lateral push 15 N s while trotting in place", as locomotion_bench prints it);
    or, for Google Benchmark figures, the benchmark names the page row gives in backticks in its
    first cell (`BM_...`), looked up in results/<name>.json, with the bound of the row's target
    cell (">= 20x" reads the counter rtf, "p99 < 1 ms" the counter p99_us).
A row is contradicted when the output's verdict differs from the page's: the table's pass column
(and, for "caught", its measured cell saying "stayed up"; for a "<= N %" target, its error), or
the counter against the bound. Rows without output are not counted (run the benchmark first).

  bench/check_page.py [--page docs/benchmarks.md] [--results build/bench/results]
                      [--bench NAME ...] [--label TEXT] [--verbose]

--bench limits the outputs read to those of the named benchmarks (results/NAME*.txt, NAME*.json),
as bench/run.sh does for the ones it has just run. Prints each contradicted row and ends with
"<label>: N rows checked, M contradicted"; exits 1 when M > 0, 2 when the page cannot be read.
Standard library only.
"""

import argparse
import glob
import json
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def cells_of(line):
    """The cells of a markdown table line, stripped; None if the line is no table row."""
    line = line.strip()
    if not line.startswith("|") or not line.endswith("|") or len(line) < 2:
        return None
    return [c.strip() for c in line[1:-1].split("|")]


def is_separator(cells):
    return all(re.fullmatch(r":?-{3,}:?", c) for c in cells if c) and any(cells)


def plain(text):
    """A cell without markdown emphasis, lowercased."""
    return re.sub(r"[*_]", "", text).strip().lower()


class PageRow:
    def __init__(self, line_no, section, cells, header):
        self.line_no = line_no
        self.section = section
        self.cells = cells
        self.header = header

    def column(self, name):
        for i, h in enumerate(self.header):
            if plain(h) == name and i < len(self.cells):
                return self.cells[i]
        return None

    def claims(self):
        """The row's verdicts: ('met', True/False) from a "met" column, ('caught', True/False) from
        a cell that begins with "caught" or "fell"; empty when it gives none."""
        found = []
        met = self.column("met")
        if met is not None and plain(met).split(" ")[0] in ("yes", "no"):
            found.append(("met", plain(met).split(" ")[0] == "yes"))
        for cell in self.cells[1:]:
            text = plain(cell)
            if re.match(r"(caught|fell)\b", text):
                found.append(("caught", text.startswith("caught")))
                break
        return found

    def text(self):
        return "| " + " | ".join(self.cells) + " |"


def page_rows(path):
    """Every data row of every table of the page, with its section and header."""
    rows = []
    section = ""
    header = None
    previous = None
    with open(path, encoding="utf-8") as page:
        lines = page.read().split("\n")
    for number, line in enumerate(lines, start=1):
        if line.startswith("#"):
            section = line.lstrip("#").strip()
        cells = cells_of(line)
        if cells is None:
            header = None
            previous = None
            continue
        if is_separator(cells):
            header = previous
            continue
        if header is not None:
            rows.append(PageRow(number, section, cells, header))
        previous = cells
    return rows


def output_files(results, names, extension):
    if names:
        found = []
        for name in names:
            found += glob.glob(os.path.join(results, glob.escape(name) + "*" + extension))
        return sorted(set(found))
    return sorted(glob.glob(os.path.join(results, "*" + extension)))


def printed_rows(files):
    """first cell -> (cells, file) of every row of the benchmarks' printed tables; where two files
    print the same row, the newer file's wins"""
    rows = {}
    for path in sorted(files, key=os.path.getmtime):
        with open(path, encoding="utf-8", errors="replace") as out:
            for line in out:
                cells = cells_of(line)
                if cells is None or is_separator(cells) or not cells[0]:
                    continue
                rows[cells[0]] = (cells, path)
    return rows


def json_benchmarks(files):
    """benchmark name -> its entry (the median aggregate where repetitions were run)"""
    entries = {}
    for path in sorted(files, key=os.path.getmtime):
        try:
            with open(path, encoding="utf-8") as out:
                benchmarks = json.load(out).get("benchmarks", [])
        except (OSError, ValueError, AttributeError):
            continue
        medians = {}
        firsts = {}
        for bench in benchmarks:
            name = bench.get("run_name", bench.get("name", ""))
            if bench.get("run_type") == "aggregate":
                if bench.get("aggregate_name") == "median":
                    medians[name] = bench
            else:
                firsts.setdefault(name, bench)
        entries.update(firsts)
        entries.update(medians)
    return entries


def find_benchmark(entries, key):
    if key in entries:
        return entries[key]
    for name, entry in entries.items():
        if name.startswith(key + "/"):
            return entry
    return None


UNIT_TO_US = {"us": 1.0, "ms": 1000.0, "s": 1e6}


def bound_of(target):
    """(counter, comparison, value) from a target cell such as ">= 20x" or "p99 < 1 ms"."""
    text = plain(target).replace("&lt;", "<").replace("&gt;", ">")
    match = re.search(r"(>=|<=|<|>)\s*([0-9.]+)\s*(x|us|ms|s)\b", text)
    if not match:
        return None
    op, value, unit = match.group(1), float(match.group(2)), match.group(3)
    if unit == "x":
        return ("rtf", op, value)
    percentile = re.search(r"\b(p50|p99)\b", text)
    counter = percentile.group(1) + "_us" if percentile else "real_time_us"
    return (counter, op, value * UNIT_TO_US[unit])


def holds(value, op, bound):
    return {"<": value < bound, "<=": value <= bound, ">": value > bound, ">=": value >= bound}[op]


def check_printed(row, out_cells):
    """None when the printed row agrees with the page row, else the reason it does not."""
    passed = plain(out_cells[-1]) == "yes"
    measured = out_cells[2] if len(out_cells) > 2 else ""
    reasons = []
    for kind, claimed in row.claims():
        if kind == "caught":
            caught = passed and plain(measured).startswith("stayed up")
            if caught != claimed:
                reasons.append("page says %s, the benchmark printed %r (pass %s)" % (
                    "caught" if claimed else "fell", measured, out_cells[-1]))
        elif passed != claimed:
            reasons.append("page says met %s, the benchmark printed pass %s" % (
                "yes" if claimed else "no", out_cells[-1]))
        elif claimed:
            target = row.column("target") or ""
            limit = re.search(r"<=\s*([0-9.]+)\s*%", target)
            error = re.search(r"([0-9.]+)\s*%", out_cells[3]) if len(out_cells) > 3 else None
            if limit and error and float(error.group(1)) > float(limit.group(1)):
                reasons.append("page target %s, the benchmark printed an error of %s" % (target, out_cells[3]))
    return "; ".join(reasons) or None


def check_json(row, keys, entries):
    """(reason or None, checked) for a page row naming Google Benchmark figures"""
    met_claims = [claimed for kind, claimed in row.claims() if kind == "met"]
    bound = bound_of(row.column("target") or "")
    if not met_claims or bound is None:
        return None, False
    claimed = met_claims[0]
    counter, op, value = bound
    figures = []
    for key in keys:
        entry = find_benchmark(entries, key)
        if entry is None:
            return None, False
        if counter == "real_time_us":
            scale = {"ns": 1e-3, "us": 1.0, "ms": 1e3, "s": 1e6}[entry.get("time_unit", "ns")]
            figure = entry["real_time"] * scale
        elif counter in entry:
            figure = float(entry[counter])
        else:
            return None, False
        figures.append((key, figure))
    met = all(holds(figure, op, value) for _, figure in figures)
    if met != claimed:
        shown = ", ".join("%s %s %.4g" % (key, counter, figure) for key, figure in figures)
        return "page says met %s for %s %s %g; the benchmark gave %s" % (
            "yes" if claimed else "no", counter, op, value, shown), True
    return None, True


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--page", default=os.path.join(ROOT, "docs", "benchmarks.md"))
    parser.add_argument("--results", default=os.path.join(ROOT, "build", "bench", "results"))
    parser.add_argument("--bench", nargs="*", default=[], help="only the outputs of these benchmarks")
    parser.add_argument("--label", default="check_page.py")
    parser.add_argument("--verbose", action="store_true", help="also list the rows checked and not checked")
    args = parser.parse_args()

    try:
        rows = [r for r in page_rows(args.page) if r.claims()]
    except OSError as error:
        print("%s: cannot read the page: %s" % (args.label, error), file=sys.stderr)
        return 2
    printed = printed_rows(output_files(args.results, args.bench, ".txt"))
    entries = json_benchmarks(output_files(args.results, args.bench, ".json"))

    checked = 0
    contradicted = 0
    unchecked = []
    for row in rows:
        keys = re.findall(r"`((?:BM_|solve_qp/)[^`]+)`", row.cells[0])
        if keys:
            reason, was_checked = check_json(row, keys, entries)
        elif row.cells[0] in printed:
            out_cells, path = printed[row.cells[0]]
            reason, was_checked = check_printed(row, out_cells), True
        else:
            reason, was_checked = None, False
        if not was_checked:
            unchecked.append(row)
            continue
        checked += 1
        if reason:
            contradicted += 1
            print("CONTRADICTED docs line %d (%s):\n  %s\n  %s" % (row.line_no, row.section, row.text(), reason))
        elif args.verbose:
            print("ok  line %d: %s" % (row.line_no, row.cells[0]))
    if args.verbose:
        for row in unchecked:
            print("not checked (no output for it in %s): line %d: %s" % (args.results, row.line_no, row.cells[0]))
    elif unchecked:
        print("%s: %d rows with a verdict had no output to compare (--verbose lists them)" % (args.label, len(unchecked)))
    print("%s: %d rows checked, %d contradicted" % (args.label, checked, contradicted))
    return 1 if contradicted else 0


if __name__ == "__main__":
    sys.exit(main())
