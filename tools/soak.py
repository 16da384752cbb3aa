#!/usr/bin/env python3
"""Soak benchmark (issue 17): many cases through a persistent external
rasterizer that crashes on 1 %, hangs on 1 % and writes garbage on 1 % of
them. A command, not a timed test; RELIABILITY.md holds its numbers.

    cargo build --release
    python3 tools/soak.py                 # 10 000 cases
    python3 tools/soak.py --cases 500     # a quick run

It writes N cases (copies of the bundled triangle cases under distinct
names) into a temporary folder and runs `rastercheck run --report` twice
against tools/soak/faulty_rasterizer.py: once with --clean (no faults), once
with its faults. While the faulty run runs it samples the rastercheck
process every --interval seconds: resident memory (VmRSS), threads, open
file descriptors, and the processes below it. Then it checks:

- every case the program did not fault has the same status and verdict in
  both reports;
- every faulted case is an error: a crash or garbage is status `ran` with
  verdict `error`, a hang is `limit-exceeded` (the --case-timeout deadline);
- both reports are complete and list every case; every case of the clean
  run passes or fails, and it exits 0 or 1; the faulty run exits 2 when a
  case hung (a case over a limit, SPEC.md §9);
- faults cost no memory: the faulty run's RSS at 50 and 90 % of the cases
  and its peak are within 10 % + 8 MiB of the clean run's (both grow by the
  report entry of each case, kept for report.json);
- threads and fds are flat: the fewest seen from 80 % of the cases on no
  more than the most seen in the first 10 % (a leak raises the floor; a
  report file being written or a program being replaced raises a sample),
  and at most 2 processes per thread below rastercheck;
- no process the run started is left afterwards (by process group).

It prints a markdown table and exits 1 if a check fails. Standard library only.
"""

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PROGRAM = os.path.join(ROOT, "tools", "soak", "faulty_rasterizer.py")
sys.path.insert(0, os.path.dirname(PROGRAM))
from faulty_rasterizer import fault_of  # noqa: E402


def write_cases(folder, count):
    """`count` cases under folder/cases/soak: the bundled triangle cases in
    turn, each renamed `TEMPLATE_NNNNN`. Returns {case id: case name}."""
    src = os.path.join(ROOT, "cases", "triangles")
    templates = sorted(f for f in os.listdir(src) if f.endswith(".json"))
    texts = {}
    for f in templates:
        with open(os.path.join(src, f)) as fh:
            texts[f] = json.load(fh)
    out = os.path.join(folder, "cases", "soak")
    os.makedirs(out)
    ids = {}
    for i in range(count):
        f = templates[i % len(templates)]
        case = dict(texts[f])
        name = "%s_%05d" % (f[: -len(".json")], i)
        case["name"] = name
        with open(os.path.join(out, name + ".json"), "w") as fh:
            json.dump(case, fh)
        ids["soak/" + name] = name
    return ids


def proc_table():
    """{pid: (ppid, pgid)} of every process."""
    table = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open("/proc/%s/stat" % entry) as fh:
                stat = fh.read()
        except OSError:
            continue
        fields = stat.rsplit(")", 1)[1].split()
        table[int(entry)] = (int(fields[1]), int(fields[2]))
    return table


def descendants(pid, table):
    children = {}
    for p, (ppid, _) in table.items():
        children.setdefault(ppid, []).append(p)
    found, stack = [], [pid]
    while stack:
        for c in children.get(stack.pop(), []):
            found.append(c)
            stack.append(c)
    return found


def sample(pid):
    """(rss KiB, threads, fds, processes below) of pid, or None."""
    try:
        with open("/proc/%d/status" % pid) as fh:
            status = dict(line.split(":", 1) for line in fh if ":" in line)
        fds = len(os.listdir("/proc/%d/fd" % pid))
    except (OSError, ValueError):
        return None
    if "VmRSS" not in status:  # a zombie: it has exited
        return None
    below = descendants(pid, proc_table())
    return (
        int(status["VmRSS"].split()[0]),
        int(status["Threads"]),
        fds,
        len(below),
    )


def run(binary, folder, clean, args, interval):
    """Runs rastercheck on folder's cases; returns (exit code, seconds,
    samples [(seconds, cases done, rss KiB, threads, fds, processes below)],
    process groups of the programs it started). Cases done: the requests
    the programs have read (rastercheck prints its lines only at the end)."""
    name = "clean" if clean else "faulty"
    progress_path = os.path.join(folder, "progress-%s.log" % name)
    open(progress_path, "w").close()
    rasterizer = "external-persistent:python3 %s --log %s%s" % (
        PROGRAM, progress_path, " --clean" if clean else "")
    command = [binary, "run", "cases", "-q", "--report", "report-" + name, "-r", rasterizer,
               "--threads", str(args.threads), "--case-timeout", str(args.case_timeout)]
    samples, groups = [], set()
    started = time.monotonic()
    with open(os.path.join(folder, name + ".log"), "wb") as log, \
            open(progress_path, "rb") as progress:
        child = subprocess.Popen(command, cwd=folder, stdout=log, stderr=subprocess.STDOUT)
        done, partial = 0, b""

        def follow():
            nonlocal done, partial
            lines = (partial + progress.read()).split(b"\n")
            partial = lines.pop()
            for line in lines:
                if line.startswith(b"pgid "):
                    groups.add(int(line.split()[1]))
                else:
                    done += 1

        while child.poll() is None:
            follow()
            s = sample(child.pid)
            if s is not None and done > 0:
                samples.append((time.monotonic() - started, done) + s)
            time.sleep(interval)
        follow()
    return child.returncode, time.monotonic() - started, samples, groups


def rss_at(samples, done):
    """RSS (KiB) of the first sample with at least `done` cases done."""
    for s in samples:
        if s[1] >= done:
            return s[2]
    return samples[-1][2]


def slope(samples, count):
    """KiB of RSS per case, between 10 % and 90 % of the cases."""
    a, b = int(count * 0.1), int(count * 0.9)
    return (rss_at(samples, b) - rss_at(samples, a)) / max(1, b - a)


def verdicts(path):
    with open(path) as fh:
        report = json.load(fh)
    out = {}
    for case in report["cases"]:
        results = case.get("results") or [{}]
        out[case["id"]] = (case["status"], results[0].get("verdict"))
    return report["complete"], out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cases", type=int, default=10000)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--case-timeout", type=float, default=2.0)
    parser.add_argument("--interval", type=float, default=0.5, help="seconds between samples")
    parser.add_argument("--binary", default=os.path.join(ROOT, "target", "release", "rastercheck"))
    parser.add_argument("--keep", action="store_true", help="keep the temporary folder")
    parser.add_argument("--csv", help="write both runs' samples to this file")
    args = parser.parse_args()
    if not os.path.exists(args.binary):
        sys.exit("no %s: run `cargo build --release` first" % args.binary)

    folder = tempfile.mkdtemp(prefix="rastercheck-soak-")
    failures = []
    try:
        ids = write_cases(folder, args.cases)
        faults = {i: fault_of(n) for i, n in ids.items() if fault_of(n)}

        code_c, secs_c, clean_samples, _ = run(args.binary, folder, True, args, args.interval)
        code_f, secs_f, samples, groups = run(args.binary, folder, False, args, args.interval)
        if args.csv:
            with open(args.csv, "w") as fh:
                fh.write("run,seconds,cases_done,rss_kib,threads,fds,processes\n")
                for name, rows in (("clean", clean_samples), ("faulty", samples)):
                    for row in rows:
                        fh.write("%s,%.2f,%d,%d,%d,%d,%d\n" % ((name,) + row))

        complete_c, clean = verdicts(os.path.join(folder, "report-clean", "report.json"))
        complete_f, faulty = verdicts(os.path.join(folder, "report-faulty", "report.json"))
        if not (complete_c and complete_f):
            failures.append("a report is not complete")
        if set(clean) != set(ids) or set(faulty) != set(ids):
            failures.append("a report does not list every case")
        # The clean run judges every case (SPEC.md §9: 0 or 1); the faulty
        # one has cases over the time limit (2) as soon as one hangs.
        if code_c not in (0, 1):
            failures.append("the clean run exited %d, not 0 or 1" % code_c)
        errors = sum(1 for v in clean.values() if v[1] != "pass" and v[1] != "fail")
        if errors:
            failures.append("%d cases of the clean run are neither pass nor fail" % errors)
        expected_code = 2 if "hang" in faults.values() else max(code_c, 1 if faults else 0)
        if code_f != expected_code:
            failures.append("the faulty run exited %d, not %d" % (code_f, expected_code))

        same = differ = 0
        by_fault = {f: {"expected": 0, "other": 0} for f in ("crash", "hang", "garbage")}
        for i in ids:
            fault = faults.get(i)
            if fault is None:
                if clean.get(i) == faulty.get(i):
                    same += 1
                else:
                    differ += 1
                    if differ <= 10:
                        failures.append("%s: clean %s, faulty %s" % (i, clean.get(i), faulty.get(i)))
            else:
                expected = ("limit-exceeded", "error") if fault == "hang" else ("ran", "error")
                if faulty.get(i) == expected:
                    by_fault[fault]["expected"] += 1
                else:
                    by_fault[fault]["other"] += 1
                    failures.append("%s (%s): %s, expected %s" % (i, fault, faulty.get(i), expected))
        if differ:
            failures.append("%d unfaulted cases changed verdict" % differ)

        # Flatness. Every case's report entry is kept for report.json, in the
        # clean run as in the faulty one: RSS is judged
        # against the clean run's at the same number of cases done, threads
        # and fds against the first 10 % of the faulty run.
        if min(len(samples), len(clean_samples)) < 10:
            failures.append("fewer than 10 samples: the run was too short to judge")
        n = args.cases
        # A leak per fault grows with the faults: judged at 50 and 90 % of
        # the cases and at the end (the report written). Earlier the runs'
        # allocations differ by some MiB either way (the faulty run's
        # threads wait on hangs while the other works), which is no leak.
        points = [(0.5, rss_at(samples, n // 2), rss_at(clean_samples, n // 2)),
                  (0.9, rss_at(samples, n * 9 // 10), rss_at(clean_samples, n * 9 // 10)),
                  (1.0, max(s[2] for s in samples), max(s[2] for s in clean_samples))]
        for fraction, faulty_rss, clean_rss in points:
            if faulty_rss > clean_rss * 1.1 + 8192:
                failures.append("RSS at %d %% of the cases: %d KiB, the clean run's %d KiB"
                                % (fraction * 100, faulty_rss, clean_rss))
        # A leak raises the floor; a file being written or a program being
        # replaced when a sample is taken raises one sample. So the fewest
        # seen over the last fifth of the cases is held to the most seen
        # over the first tenth.
        first = [s for s in samples if s[1] <= n * 0.1] or samples[:1]
        late = [s for s in samples if n * 0.8 <= s[1] < n] or samples[-1:]
        for k, what in ((3, "threads"), (4, "fds")):
            most = max(s[k] for s in first)
            floor = min(s[k] for s in late)
            if floor > most:
                failures.append("%s grew from at most %d (first 10 %% of the cases) to at least %d"
                                " (80 %% on)" % (what, most, floor))
        if max(s[5] for s in samples) > 2 * args.threads:
            failures.append("more than 2 processes per thread at once")

        # No process of the run's groups is left (a killed one may take a
        # moment to be reaped).
        if not groups:
            failures.append("the programs logged no process group")
        left = None
        for _ in range(50):
            left = [p for p, (_, g) in proc_table().items() if g in groups]
            if not left:
                break
            time.sleep(0.1)
        if left:
            failures.append("processes left in the run's groups: %s" % left)

        # The tables.
        def at_cases(rows, k, fraction):
            return next((r for r in rows if r[1] >= n * fraction), rows[-1])[k]

        def row(rows, k, scale=1.0, fmt="%d"):
            values = [r[k] / scale for r in rows]
            cells = [values[0]] + [at_cases(rows, k, f) / scale for f in (0.1, 0.5, 0.9)]
            cells += [max(values), values[-1]]
            return " | ".join(fmt % v for v in cells)

        print("## Soak: %d cases, %d threads, --case-timeout %g s\n"
              % (n, args.threads, args.case_timeout))
        print("| run | exit code | seconds |\n|---|---|---|")
        print("| clean (`--clean`) | %d | %.1f |" % (code_c, secs_c))
        print("| faulty | %d | %.1f |\n" % (code_f, secs_f))
        print("| faulted cases | count | as expected |\n|---|---|---|")
        for f, expected in (("crash", "error"), ("hang", "limit-exceeded, error"), ("garbage", "error")):
            total = by_fault[f]["expected"] + by_fault[f]["other"]
            print("| %s | %d | %d (%s) |" % (f, total, by_fault[f]["expected"], expected))
        print("| not faulted | %d | %d same status and verdict as the clean run, %d differ |\n"
              % (same + differ, same, differ))
        print("Sampled every %g s (clean %d samples, faulty %d), by cases done:\n"
              % (args.interval, len(clean_samples), len(samples)))
        print("| | first sample | 10 % | 50 % | 90 % | max | last sample |")
        print("|---|---|---|---|---|---|---|")
        print("| RSS, clean run (MiB) | %s |" % row(clean_samples, 2, 1024.0, "%.1f"))
        print("| RSS, faulty run (MiB) | %s |" % row(samples, 2, 1024.0, "%.1f"))
        print("| threads, faulty run | %s |" % row(samples, 3))
        print("| open fds, faulty run | %s |" % row(samples, 4))
        print("| processes below it, faulty run | %s |" % row(samples, 5))
        print("\nRSS per case kept (10 %% to 90 %% of the cases): clean %.1f KiB, faulty %.1f KiB"
              % (slope(clean_samples, n), slope(samples, n)))
        print("programs started (process groups): %d; processes of them left after the run: %d\n"
              % (len(groups), len(left or [])))
        if failures:
            print("FAILED:")
            for f in failures:
                print("- " + f)
        else:
            print("All checks passed.")
    finally:
        if args.keep:
            print("kept: %s" % folder)
        else:
            shutil.rmtree(folder, ignore_errors=True)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
