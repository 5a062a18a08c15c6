"""Reads the lines of tests/paraview/scale.py (every rank of every run) and
prints per rank count the median and range over runs of the times of
ShadeLab Normals (its first update, which on several ranks runs the source
again, and the filter alone) and ShadeLab Radiance, and the largest RSS of any rank, as a Markdown table. Ranks wait
for each other at a barrier after each step, so a run's time is any rank's."""
import re
import statistics
import sys

LINE = re.compile(r"ranks (\d+) rank (\d+): (\d+) triangles, (\d+) threads of (\w+), normals ([\d.]+) s "
                  r"\(filter alone ([\d.]+) s\), radiance ([\d.]+) s, max RSS (\d+) MB")

runs = {}  # ranks -> list of [normals, normals alone, radiance, rss] per run
seen = {}  # ranks -> ranks of the current run reported so far
for line in sys.stdin:
    m = LINE.search(line)
    if not m:
        continue
    ranks, threads = int(m[1]), int(m[4])
    values = [float(m[6]), float(m[7]), float(m[8]), int(m[9])]
    if seen.get(ranks, 0) % ranks == 0:
        runs.setdefault(ranks, []).append([0.0, 0.0, 0.0, 0, threads])
    seen[ranks] = seen.get(ranks, 0) + 1
    run = runs[ranks][-1]
    run[:4] = [max(a, b) for a, b in zip(run, values)]


def cell(values, serial=None):
    text = "%.2f s (%.2f–%.2f)" % (statistics.median(values), min(values), max(values))
    if serial is not None:
        text += ", %.2f×" % (serial / statistics.median(values))
    return text


print("| ranks | threads per rank | runs | normals, first update | normals alone | radiance | max RSS per rank |")
print("|---|---|---|---|---|---|---|")
serial = runs.get(1)
for ranks in sorted(runs):
    r = runs[ranks]
    columns = []
    for k in range(3):
        base = statistics.median([x[k] for x in serial]) if serial else None
        columns.append(cell([x[k] for x in r], base))
    print("| %d | %d | %d | %s | %d MB |" % (ranks, r[0][4], len(r), " | ".join(columns), max(x[3] for x in r)))
