"""The generated figures of REPORT.md and docs/*.md (issues 11, 26): one function per `<!-- fig:NAME -->` block, each
making Markdown from the CSVs in bench/results/. Numbers are never typed here, only read."""
import math
import os
import subprocess

from results import GoogleBenchmark, MissingData, by_keys, read_csv

COMMAND = "`bash bench/make_report.sh`"


def sig(x, digits=3):
    """x to `digits` significant digits, without an exponent for everyday magnitudes."""
    if x == 0 or not math.isfinite(x):
        return "%g" % x
    exponent = math.floor(math.log10(abs(x)))
    if -4 <= exponent < 6:
        return "%.*f" % (max(digits - 1 - exponent, 0), x)
    return "%.*e" % (digits - 1, x)


def si(x, digits=3):
    """x with a k/M/G suffix."""
    for factor, suffix in ((1e9, " G"), (1e6, " M"), (1e3, " k")):
        if abs(x) >= factor:
            return sig(x / factor, digits) + suffix
    return sig(x, digits)


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines) + "\n"


def path(results, name):
    return os.path.join(results, name)


def committed_on(csv_path):
    """The day a CSV was last committed (git), or None outside a checkout."""
    try:
        out = subprocess.run(["git", "log", "-1", "--format=%cs", "--", os.path.basename(csv_path)],
                             cwd=os.path.dirname(os.path.abspath(csv_path)), capture_output=True, text=True,
                             check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return None
    return out or None


def machine(results):
    m = {r["key"]: r["value"] for r in read_csv(path(results, "machine.csv"))}
    text = (f"The benchmarks' last {m['mode']} run by {COMMAND} ({m['date']}, commit {m['commit']}, "
            f"{m['bench_seconds']} s): {m['cpu']}, {m['nproc']} cores, {m['memory_gib']} GiB, {m['os']}, "
            f"{m['compiler']}, Release; load {m['load_before']} before, {m['load_after']} after, shared with "
            f"other builds (under `nice -n 19`): timings are noisy, errors and counts exact.")
    # The CSVs single benchmarks rewrote after that run (issue 55: the blocks and plots mix dates, so
    # each is named with the day it was committed).
    run_day = m["date"][:10]
    later = {}
    for name in sorted(os.listdir(results)):
        if name.endswith(".csv") and name != "machine.csv":
            day = committed_on(path(results, name))
            if day is not None and day > run_day:
                later.setdefault(day, []).append(name[:-4])
    if later:
        text += (" CSVs rewritten since by single runs: " +
                 "; ".join(f"{', '.join(names)} ({day[5:]})" for day, names in sorted(later.items())) + ".")
    return text + "\n"


def particles(results):
    gb = GoogleBenchmark(path(results, "particles.csv"))
    counts = sorted(int(n.split("/")[1]) for n in gb.rows if n.startswith("step/"))
    memcpy = [n for n in gb.rows if n.startswith("memcpy/")]
    if not counts or not memcpy:
        raise MissingData(gb.path + ": no step or memcpy runs")
    bandwidth = gb.value(memcpy[0], "bytes_per_second")
    rows = []
    for n in counts:
        rate = gb.value("step/%d" % n, "items_per_second")
        bound = bandwidth / gb.value("step/%d" % n, "bytes_per_particle_step")
        rows.append([si(n, 2), si(rate), sig(1e9 / rate), sig(bound / rate)])
    out = table(["particles", "particle-steps/s", "ns per particle-step", "memory bound / measured"], rows)
    bytes_step = gb.value("step/%d" % counts[-1], "bytes_per_particle_step")
    state = gb.value("step/%d" % counts[-1], "state_bytes_per_particle")
    out += (f"\nBytes per particle-step {bytes_step:.0f} (state {state:.0f} B per particle); memcpy out of cache "
            f"{sig(bandwidth / 1e9)} GB/s (read + written), so the bound is {si(bandwidth / bytes_step)} "
            "particle-steps/s. Rates are per CPU second of the benchmark's thread.\n")
    render = []
    for label, name in (("no sprites", "render_no_sprites"), ("1e5 additive sprites", "render_1e5_sprites/additive"),
                        ("1e5 alpha sprites", "render_1e5_sprites/alpha")):
        render.append([label, sig(1.0 / gb.seconds(name, "real_time")), sig(1e3 * gb.seconds(name, "real_time"))])
    out += "\n" + table(["1280x720 frame (llvmpipe, read back)", "frames/s", "ms per frame"], render)
    out += (f"\nBuilding the 1e5 sprites from the World: {sig(1e3 * gb.seconds('build_1e5_sprites/additive'))} ms "
            f"additive, {sig(1e3 * gb.seconds('build_1e5_sprites/alpha'))} ms alpha (sorted back to front).\n")
    return out


def step(results):
    gb = GoogleBenchmark(path(results, "step.csv"))
    rows = [[name.replace("_", "-"), sig(1e6 * gb.seconds("stepBox/" + name))]
            for name in ("euler_matrix", "euler_quat", "expmap")]
    out = table(["one World::step of a box", "µs"], rows)
    sphere = [n for n in gb.rows if n.startswith("stepSphere/")]
    mass = [n for n in gb.rows if n.startswith("massProperties/")]
    if not sphere or not mass:
        raise MissingData(gb.path + ": no stepSphere or massProperties runs")
    out += "\n" + table(
        ["mesh", "step + world vertices (expmap) [µs]", "exact mass properties [µs]"],
        [[f"{gb.value(s, 'vertices'):.0f} vertices, {gb.value(m, 'triangles'):.0f} triangles",
          sig(1e6 * gb.seconds(s)), sig(1e6 * gb.seconds(m))] for s, m in zip(sphere, mass)])
    return out


def throughput(results):
    gb = GoogleBenchmark(path(results, "throughput.csv"))
    names = list(dict.fromkeys(n.split("/")[1] for n in gb.rows if n.startswith("step/")))
    counts = sorted({int(n.split("/")[2]) for n in gb.rows if n.startswith("step/")})
    biggest_copy = max((n for n in gb.rows if n.startswith("memcpy/")), key=lambda n: int(n.split("/")[1]))
    bandwidth = gb.value(biggest_copy, "bytes_per_second")
    rows = []
    for name in names:
        rates = [si(gb.value("step/%s/%d" % (name, n), "items_per_second")) for n in counts]
        bytes_step = gb.value("step/%s/%d" % (name, counts[-1]), "bytes_per_body")
        measured = gb.value("step/%s/%d" % (name, counts[-1]), "items_per_second")
        rows.append([name] + rates + ["%.0f" % bytes_step, sig(bandwidth / bytes_step / measured)])
    header = ["integrator"] + ["%s bodies" % si(n, 2) for n in counts] + [
        "bytes per body-step", "bound / measured at %s" % si(counts[-1], 2)]
    return (table(header, rows) + f"\nBody-steps per second (collisions off, gravity on, no sleeping); memcpy out of "
            f"cache {sig(bandwidth / 1e9)} GB/s (read + written) over the bytes a body-step reads and writes is the "
            "memory bound.\n")


def stage_skip(results):
    gb = GoogleBenchmark(path(results, "stage_skip.csv"))
    counts = sorted({int(n.split("/")[2]) for n in gb.rows if n.startswith("stages/")})
    rows = []
    for n in counts:
        for label, full, skip in (("moving, skipIdleStages", "stages/run_all", "stages/skip_idle"),
                                  ("at rest, allowSleep", "rest/no_sleep", "rest/sleep")):
            a, b = gb.seconds("%s/%d" % (full, n)), gb.seconds("%s/%d" % (skip, n))
            rows.append([si(n, 2), label, sig(1e6 * a), sig(1e6 * b), sig(a / b) + "x"])
    return table(["bodies", "case", "every stage [µs/step]", "skipping [µs/step]", "saving"], rows)


def broadphase(results):
    gb = GoogleBenchmark(path(results, "broadphase.csv"))
    counts = sorted({int(n.split("/")[1]) for n in gb.rows if n.startswith("sapCoherent/")})
    columns = (("sapCoherent", "SAP coherent"), ("sapCoherentFixedSwaps", "SAP, fixed swaps per box"),
               ("sapTeleport", "SAP, every box teleports"), ("bruteCoherent", "brute force"))
    rows = []
    for n in counts:
        row = [si(n, 2)]
        for key, _ in columns:
            name = "%s/%d" % (key, n)
            row.append(sig(gb.value(name, "ms_per_update")) if gb.has(name) else "not run")
        row += ["%.0f" % gb.value("sapCoherent/%d" % n, "pairs"), sig(gb.value("sapCoherent/%d" % n, "swaps"))]
        rows.append(row)
    out = table(["boxes"] + ["%s [ms]" % label for _, label in columns] + ["pairs", "swaps per update"], rows)
    lo, hi = counts[0], counts[-1]

    def slope(key):
        a, b = gb.value("%s/%d" % (key, lo), "ms_per_update"), gb.value("%s/%d" % (key, hi), "ms_per_update")
        return math.log(b / a) / math.log(hi / lo)

    return out + (f"\nFrom {si(lo, 2)} to {si(hi, 2)} boxes the coherent update grows as N^{slope('sapCoherent'):.2f}, "
                  f"with a fixed number of swaps per box as N^{slope('sapCoherentFixedSwaps'):.2f}, brute force as "
                  f"N^{slope('bruteCoherent'):.2f}. Times are CPU time of the benchmark's thread per update.\n")


def pile(results):
    rows = read_csv(path(results, "pile.csv"))
    index = by_keys(rows, "engine", "boxes", "sleep")
    engines = [e for e in ("soft-step", "pgs", "bullet-float", "bullet-double") if any(r["engine"] == e for r in rows)]
    counts = sorted({int(r["boxes"]) for r in rows if r["engine"] == "soft-step"})
    out_rows = []
    for n in counts:
        cells = [str(n)]
        for e in engines:
            r = index.get((e, str(n), "off"))
            cells.append(sig(float(r["ms_per_step"])) if r else "not run")
        for e in engines[:3]:
            r = index.get((e, str(n), "off"))
            cells.append("%s, %s mm, %s m/s" % (r["contact_points"], sig(1e3 * float(r["deepest_m"]), 2),
                                                 sig(float(r["fastest_m_per_s"]), 2)) if r else "not run")
        out_rows.append(cells)
    header = ["boxes"] + ["%s [ms/step]" % e for e in engines] + [
        "%s at 10 s: points, deepest, fastest" % e for e in engines[:3]]
    out = table(header, out_rows)
    asleep = []
    for e in engines:
        r = index.get((e, str(counts[0]), "on"))
        if r:
            asleep.append("%s %s ms/step with %s of %d boxes awake" % (e, sig(float(r["ms_per_step"])), r["awake"],
                                                                       counts[0]))
    out += "\nSleep off above (every box simulated every step). With sleep on, %d boxes at 10 s: %s.\n" % (
        counts[0], "; ".join(asleep))
    stages = [r for r in read_csv(path(results, "pile_stages.csv"))
              if r["engine"] == "soft-step" and r["boxes"] == str(counts[-1]) and r["sleep"] == "off"]
    if not stages:
        raise MissingData("pile_stages.csv: no soft-step rows for %d boxes" % counts[-1])
    shares = sorted(stages, key=lambda r: -float(r["percent"]))
    out += "rbsim's stages (soft step) at %d boxes: %s.\n" % (
        counts[-1], ", ".join("%s %s %%" % (r["stage"], sig(float(r["percent"]), 2)) for r in shares))
    return out


def soft(results):
    rows = read_csv(path(results, "soft.csv"))
    out = [[r["tets"], "%.0e Pa" % float(r["youngs_modulus_pa"]), r["integrator"], sig(1e3 * float(r["dt_s"])),
            sig(1e3 * float(r["stable_explicit_dt_s"])) if r["integrator"] == "symplectic-euler" else "",
            sig(float(r["ms_per_step"])), sig(float(r["cg_iterations"]), 2) if r["integrator"] != "symplectic-euler"
            else "", sig(float(r["ms_per_simulated_s"]))] for r in rows]
    return table(["tetrahedra", "E", "integrator", "dt [ms]", "stable explicit dt [ms]", "ms/step", "CG iterations",
                  "ms per simulated s"], out)


def accuracy(results):
    rows = [r for r in read_csv(path(results, "accuracy.csv")) if r["case"] == "torque-free-box"]
    at60 = [r for r in rows if r["steps_per_s"] == "60"]
    if not at60:
        raise MissingData("accuracy.csv: no torque-free-box rows at dt = 1/60 s")

    def flips(r):
        if r["flip_status"] == "no-flip":
            return "stopped flipping"
        return "%s %% (%s flips, exact %s)" % (sig(100 * float(r["flip_period_err_rel"]), 2), r["flip_count"],
                                              r["flip_count_exact"])

    out = table(["integrator", "ns/step", "max orientation error [rad]",
                 "in the first %s s [rad]" % sig(float(at60[0]["early_horizon_s"]), 2), "max \\|E/E0 - 1\\|",
                 "flip half-period error"],
                [[r["integrator"], sig(float(r["wall_ns_per_step"])), sig(float(r["orient_err_max_rad"])),
                  sig(float(r["orient_err_max_early_rad"]), 2), sig(float(r["energy_drift_max_rel"]), 2), flips(r)]
                 for r in at60])
    sim = float(at60[0]["sim_time_s"])
    best = []
    for budget_us in (20, 50, 100, 500):  # wall time per simulated second [µs]
        within = [r for r in rows if 1e3 * float(r["wall_ms_per_run"]) / sim <= budget_us]
        if within:
            r = min(within, key=lambda r: float(r["orient_err_max_rad"]))
            best.append("%d µs: %s at 1/%s s (%s rad)" % (budget_us, r["integrator"], r["steps_per_s"],
                                                         sig(float(r["orient_err_max_rad"]), 2)))
    out += ("\nTorque-free box, dt = 1/60 s, %s s simulated, exact flip half-period %s s. Smallest max orientation "
            "error within a wall-time budget per simulated second: %s.\n" % (
                sig(sim), sig(float(at60[0]["flip_half_period_exact_s"]), 5), "; ".join(best)))
    projectile = [r for r in read_csv(path(results, "accuracy.csv"))
                  if r["case"] != "torque-free-box" and r["steps_per_s"] == "60" and "projectile" in r["case"]]
    if projectile:
        out += "Spinning projectile at dt = 1/60 s, max position error: %s.\n" % ", ".join(
            "%s %s m" % (r["integrator"], sig(float(r["position_err_max_m"]), 2)) for r in projectile)
    torqued = [r for r in read_csv(path(results, "accuracy.csv")) if r["case"] == "torqued-box" and r["steps_per_s"] == "60"]
    if torqued:
        out += "Box under a body-fixed torque at dt = 1/60 s, max orientation error against RK4 at 1/30000 s: %s.\n" % ", ".join(
            "%s %s rad" % (r["integrator"], sig(float(r["orient_err_max_rad"]), 2)) for r in torqued)
    return out


def frame_pipeline(results):
    rows = read_csv(path(results, "frame_pipeline.csv"))
    columns = ["bench", "build", "round", "frames", "wall_s", "cpu_s", "fps", "video_s", "load1", "render_ms",
               "png_ms", "video_ms"]
    for c in columns:
        if c not in rows[0]:
            raise MissingData("frame_pipeline.csv has no column " + c)
    return table(["bench", "build", "round", "frames", "wall [s]", "CPU [s]", "frames / wall s", "video plays [s]",
                  "load (1 min)", "render [ms/frame]", "PNG [ms/frame]", "video [ms/frame]"],
                 [[r["bench"], r["build"], r["round"], r["frames"]] + [sig(float(r[c])) if r[c] else "" for c in columns[4:]]
                  for r in rows])


def sdf_contact(results):
    rows = read_csv(path(results, "sdf_contact.csv"))
    return table(["grid resolution", "sample spacing [cells]", "bowl samples", "grid build [ms]",
                  "narrow phase [ms/step]", "resting height error [m]", "deepest contact [m]"],
                 [[r["resolution"], r["spacing_cells"] if float(r["spacing_cells"]) > 0 else "vertices only",
                   r["samples"], sig(float(r["build_ms"])), sig(float(r["narrow_ms"])),
                   sig(float(r["height_err_m"]), 2), sig(float(r["deepest_m"]), 2)] for r in rows])


def sdf(results):
    rows = read_csv(path(results, "sdf.csv"))
    columns = ["shape", "resolution", "points", "build_ms", "max_err_m", "rms_err_m", "max_err_cells", "query_ns"]
    for c in columns:
        if c not in rows[0]:
            raise MissingData("sdf.csv has no column " + c)
    return table(["shape", "grid resolution", "surface points", "build [ms]", "max error [m]", "rms error [m]",
                  "max error [cells]", "query [ns]"],
                 [[r["shape"], r["resolution"], r["points"]] + [sig(float(r[c])) for c in columns[3:]] for r in rows])


FIGURES = {
    "machine": machine, "particles": particles, "step": step, "throughput": throughput, "stage_skip": stage_skip,
    "broadphase": broadphase, "pile": pile, "soft": soft, "accuracy": accuracy, "frame_pipeline": frame_pipeline,
    "sdf": sdf, "sdf_contact": sdf_contact,
}
OPTIONAL = set()  # figures whose CSV may be missing (skipped with a warning); none now
