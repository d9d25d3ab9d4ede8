#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Prints a study.csv of `formflow study` as a Markdown table (for docs/verification.md).
# Usage: bench/study_table.py DIR/study.csv [column ...]
# Default columns: value, dofs, iterations, stop_reason and every column with a value.
import csv
import sys

NAMES = {
    "value": "value", "dofs": "dofs", "iterations": "its", "stop_reason": "stop",
    "ram_reaction": "p (ram)", "power_balance": "p (power)", "error_V": "‖e‖_V",
    "error_L2": "‖e‖_L2", "error_hydrostatic_L2": "‖σ_H,h‖_L2", "difference_V": "‖u − u_ref‖_V",
    "difference_L2": "‖u − u_ref‖_L2", "order_V": "order V", "order_L2": "order L2",
    "pressure_order": "order p", "pressure_extrapolated": "Richardson p", "rcond": "rcond",
}


def cell(name, text):
    if text == "":
        return "–"
    if name in ("value", "dofs", "iterations", "stop_reason"):
        return text
    number = float(text)
    if name.startswith("order") or name == "pressure_order":
        return f"{number:.2f}"
    if name in ("ram_reaction", "power_balance", "pressure_extrapolated"):
        return f"{number:.4f}"
    return f"{number:.3e}"


def main(path, columns):
    with open(path, newline="") as stream:
        rows = list(csv.DictReader(stream))
    if not columns:
        columns = [c for c in NAMES if c in ("value", "dofs", "iterations", "stop_reason")
                   or any(row[c] for row in rows)]
    print("| " + rows[0]["key"] + " | " + " | ".join(NAMES[c] for c in columns[1:]) + " |")
    print("|" + "---|" * len(columns))
    for row in rows:
        print("| " + " | ".join(cell(c, row[c]) for c in columns) + " |")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2:])
