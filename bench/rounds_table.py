#!/usr/bin/env python3
"""The body of a bench's markdown table from its rounds: ROWS holds one line
`NAME v1 v2 …` per case and round; each NAME (in the order first seen) gets a
row of its columns' medians over the rounds, each round's value in brackets.

  bench/rounds_table.py ROWS FORMAT...

One FORMAT a column, `M.R`: the median's decimals and the rounds' (1.0: 12.3 (12, 13)).
"""
import collections
import statistics
import sys


def main():
    rows, formats = sys.argv[1], [f.split(".") for f in sys.argv[2:]]
    runs = collections.OrderedDict()
    for line in open(rows):
        name, *values = line.split()
        runs.setdefault(name, []).append([float(v) for v in values])
    for name, rounds in runs.items():
        cells = []
        for column, (m, r) in zip(zip(*rounds), formats):
            each = ", ".join(f"{v:.{r}f}" for v in column)
            cells.append(f"{statistics.median(column):.{m}f} ({each})")
        print(f"| {name} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
