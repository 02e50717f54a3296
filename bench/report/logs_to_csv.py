"""Turns the printed lines of the benchmarks that time whole runs themselves (contact_pile,
bullet_pile, bullet_pile_double, soft_bench) into CSV files (issue 11).

usage: python3 bench/report/logs_to_csv.py LOG_DIR RESULTS_DIR
writes RESULTS_DIR/pile.csv, pile_stages.csv and soft.csv. A log line that does not parse stops
the script: a changed output format must not leave stale or missing rows silently.
"""
import csv
import os
import re
import sys

NUMBER = r"([-+0-9.eE]+)"
PILE_LINE = re.compile(
    r"^(?:(soft-step|pgs) +)?N = +(\d+), sleep (on|off) *: +" + NUMBER + r" ms/step \(median of last (\d+) of (\d+)\), +(\d+) contact points, "
    r"deepest " + NUMBER + r" m, fastest " + NUMBER + r" m/s \((at rest|moving)\), (\d+) awake")
STAGE_LINE = re.compile(r"^ {4}(\S+) +" + NUMBER + r" %$")
SOFT_LINE = re.compile(
    r"^ *(\d+) tets +E " + NUMBER + r" Pa +(\S+) +(\S+) +dt " + NUMBER + r" s \(stable explicit " + NUMBER +
    r" s\) +" + NUMBER + r" ms/step +" + NUMBER + r" CG its +" + NUMBER + r" ms per simulated s$")


def fail(message):
    sys.exit("logs_to_csv.py: " + message)


def read_lines(path):
    with open(path) as f:
        return [line.rstrip("\n") for line in f if line.strip()]


def parse_pile(log_dir):
    """Rows of the box pile for every engine whose log exists; rbsim's log must exist."""
    piles, stages = [], []
    for engine, name in (("rbsim", "contact_pile"), ("bullet-float", "bullet_pile"),
                         ("bullet-double", "bullet_pile_double")):
        path = os.path.join(log_dir, name + ".log")
        if not os.path.exists(path):
            if engine == "rbsim":
                fail("missing " + path)
            continue
        current = None
        for line in read_lines(path):
            if line.startswith("Bullet "):
                continue
            m = PILE_LINE.search(line)
            if m:
                solver, n, sleep, ms, _, _, points, deepest, fastest, rest, awake = m.groups()
                if engine == "rbsim" and not solver:
                    fail("%s: a contact_pile line without its solver: %r" % (path, line))
                label = solver if engine == "rbsim" else engine  # contact_pile runs soft-step and pgs
                current = (label, n, sleep)
                piles.append({"engine": label, "boxes": n, "sleep": sleep, "ms_per_step": ms,
                              "contact_points": points, "deepest_m": deepest, "fastest_m_per_s": fastest,
                              "at_rest": int(rest == "at rest"), "awake": awake})
                continue
            m = STAGE_LINE.match(line)
            if m and current:
                stages.append({"engine": current[0], "boxes": current[1], "sleep": current[2],
                               "stage": m.group(1), "percent": m.group(2)})
                continue
            fail("%s: unexpected line %r" % (path, line))
    return piles, stages


def parse_soft(log_dir):
    rows = []
    path = os.path.join(log_dir, "soft.log")
    for line in read_lines(path):
        m = SOFT_LINE.match(line)
        if not m:
            fail("%s: unexpected line %r" % (path, line))
        tets, e, model, integrator, dt, stable, ms, cg, per_s = m.groups()
        rows.append({"tets": tets, "youngs_modulus_pa": e, "model": model, "integrator": integrator, "dt_s": dt,
                     "stable_explicit_dt_s": stable, "ms_per_step": ms, "cg_iterations": cg,
                     "ms_per_simulated_s": per_s})
    return rows


def write(path, rows):
    if not rows:
        fail("no rows for " + path)
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)


def main():
    if len(sys.argv) != 3:
        fail("usage: logs_to_csv.py LOG_DIR RESULTS_DIR")
    log_dir, results = sys.argv[1:]
    piles, stages = parse_pile(log_dir)
    write(os.path.join(results, "pile.csv"), piles)
    write(os.path.join(results, "pile_stages.csv"), stages)
    write(os.path.join(results, "soft.csv"), parse_soft(log_dir))


if __name__ == "__main__":
    main()
