"""Reads the lines of tests/paraview/scale.py (every rank of every run) and
prints per rank count the median and range over runs of the normals and
radiance times (the slowest rank of a run: a run ends when its last rank
does) and the largest RSS of any rank, as a Markdown table."""
import re
import statistics
import sys

LINE = re.compile(r"ranks (\d+) rank (\d+): (\d+) triangles, normals ([\d.]+) s, radiance ([\d.]+) s, "
                  r"max RSS (\d+) MB")

runs = {}  # ranks -> list of [normals, radiance, rss] per run, the slowest rank
seen = {}  # ranks -> ranks of the current run reported so far
for line in sys.stdin:
    m = LINE.search(line)
    if not m:
        continue
    ranks, normals, radiance, rss = int(m[1]), float(m[4]), float(m[5]), int(m[6])
    if seen.get(ranks, 0) % ranks == 0:
        runs.setdefault(ranks, []).append([0.0, 0.0, 0])
    seen[ranks] = seen.get(ranks, 0) + 1
    run = runs[ranks][-1]
    run[0], run[1], run[2] = max(run[0], normals), max(run[1], radiance), max(run[2], rss)


def cell(values, serial=None):
    text = "%.2f s (%.2f–%.2f)" % (statistics.median(values), min(values), max(values))
    if serial is not None:
        text += ", %.2f×" % (serial / statistics.median(values))
    return text


print("| ranks | runs | normals: median (range), speed-up | radiance: median (range), speed-up | max RSS per rank |")
print("|---|---|---|---|---|")
serial = runs.get(1)
for ranks in sorted(runs):
    r = runs[ranks]
    normals, radiance = [x[0] for x in r], [x[1] for x in r]
    print("| %d | %d | %s | %s | %d MB |" % (
        ranks, len(r), cell(normals, statistics.median([x[0] for x in serial]) if serial else None),
        cell(radiance, statistics.median([x[1] for x in serial]) if serial else None), max(x[2] for x in r)))
