"""The reference deadline accounting and abort latency of docs/FORMATS.md sections 3 and 4.

A job is (task, outcome, release, start, end, abort): times in ns, -1 where there is none.
make_vectors.py writes what this computes for its cases into deadlines.txt.
"""

import math

QUANTILES = [("min", 0), ("p50", 500), ("p90", 900), ("p99", 990), ("p999", 999), ("max", 1000)]


def account(jobs, task):
    """The deadline accounting and the response time over every release of one task ('all': both)."""
    mine = [j for j in jobs if (task == "all" or j[0] == task) and j[1] != "pending"]
    n = len(mine)
    by = {o: sum(1 for j in mine if j[1] == o) for o in ("done", "late", "skipped", "terminated")}
    misses = by["late"] + by["skipped"] + by["terminated"]
    finite = sorted(j[4] - j[2] for j in mine
                    if j[1] in ("done", "late") and j[2] >= 0 and j[3] >= 0 and j[4] >= 0)
    values = finite + [math.inf] * (n - len(finite))
    quantiles = []
    for _, pm in QUANTILES:
        if n == 0:
            quantiles.append(None)
            continue
        i = min(n - 1, max(0, (pm * n + 999) // 1000 - 1))
        quantiles.append(values[i])
    return n, by, misses, (misses / n if n else None), len(finite), quantiles


def abort_from(job):
    """When an abort took hold of a job (FORMATS.md section 3, abort_ns): the request, or the start when
    requested before it; None when the job never started or nothing was requested before its end."""
    _, _, _, start, end, abort = job
    if abort < 0 or start < 0 or end < 0:
        return None
    at = max(abort, start)
    return at if at < end else None


def abort_latency(jobs, task):
    """Abort latency (end - abort_ns) over the released jobs an abort took hold of, and how many completed."""
    mine = [j for j in jobs if (task == "all" or j[0] == task) and j[1] != "pending" and abort_from(j) is not None]
    values = sorted(j[4] - abort_from(j) for j in mine)
    n = len(values)
    quantiles = [None if n == 0 else values[min(n - 1, max(0, (pm * n + 999) // 1000 - 1))] for _, pm in QUANTILES]
    return n, sum(1 for j in mine if j[1] in ("done", "late")), quantiles
