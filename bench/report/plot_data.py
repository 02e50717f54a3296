"""Writes the columns bench/report/plots.gp draws, from the benchmark CSVs (issue 11): Google
Benchmark names runs "kind/arg/...", which gnuplot cannot split, so the runs are laid out here as
whitespace-separated tables, one per plot. Missing data stops the script.

usage: python3 bench/report/plot_data.py RESULTS_DIR DATA_DIR
"""
import os
import sys

from results import GoogleBenchmark, MissingData, by_keys, read_csv

NAN = "NaN"


def write(data_dir, name, header, rows):
    with open(os.path.join(data_dir, name), "w") as f:
        f.write("# " + " ".join(header) + "\n")
        for row in rows:
            f.write(" ".join(str(c) for c in row) + "\n")


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: plot_data.py RESULTS_DIR DATA_DIR")
    results, data = sys.argv[1:]
    os.makedirs(data, exist_ok=True)

    gb = GoogleBenchmark(os.path.join(results, "broadphase.csv"))
    kinds = ["sapCoherent", "sapCoherentFixedSwaps", "sapTeleport", "bruteCoherent", "bruteTeleport"]
    counts = sorted({int(n.split("/")[1]) for n in gb.rows if n.startswith("sapCoherent/")})
    write(data, "broadphase.dat", ["boxes"] + kinds,
          [[n] + [gb.value("%s/%d" % (k, n), "ms_per_update") if gb.has("%s/%d" % (k, n)) else NAN for k in kinds]
           for n in counts])

    rows = read_csv(os.path.join(results, "pile.csv"))
    index = by_keys(rows, "engine", "boxes", "sleep")
    engines = ["soft-step", "pgs", "bullet-float", "bullet-double"]
    counts = sorted({int(r["boxes"]) for r in rows})
    write(data, "pile.dat", ["boxes"] + engines + [e + "-sleep" for e in engines],
          [[n] + [index[(e, str(n), s)]["ms_per_step"] if (e, str(n), s) in index else NAN
                  for s in ("off", "on") for e in engines] for n in counts])

    gb = GoogleBenchmark(os.path.join(results, "particles.csv"))
    memcpy = [n for n in gb.rows if n.startswith("memcpy/")]
    if not memcpy:
        raise MissingData(gb.path + ": no memcpy run")
    bandwidth = gb.value(memcpy[0], "bytes_per_second")
    counts = sorted(int(n.split("/")[1]) for n in gb.rows if n.startswith("step/"))
    write(data, "particles.dat", ["particles", "rate", "bound"],
          [[n, gb.value("step/%d" % n, "items_per_second"),
            bandwidth / gb.value("step/%d" % n, "bytes_per_particle_step")] for n in counts])

    gb = GoogleBenchmark(os.path.join(results, "throughput.csv"))
    names = list(dict.fromkeys(n.split("/")[1] for n in gb.rows if n.startswith("step/")))
    counts = sorted({int(n.split("/")[2]) for n in gb.rows if n.startswith("step/")})
    biggest = max((n for n in gb.rows if n.startswith("memcpy/")), key=lambda n: int(n.split("/")[1]))
    bandwidth = gb.value(biggest, "bytes_per_second")
    write(data, "throughput.dat", ["integrator"] + ["n%d" % n for n in counts] + ["bound"],
          [[name] + [gb.value("step/%s/%d" % (name, n), "items_per_second") / 1e6 for n in counts] +
           [bandwidth / gb.value("step/%s/%d" % (name, counts[-1]), "bytes_per_body") / 1e6] for name in names])

    rows = read_csv(os.path.join(results, "soft.csv"))
    tets = sorted({int(r["tets"]) for r in rows})
    def config(r):  # the explicit step is each mesh's own stable step, so it is not part of the key
        return (r["youngs_modulus_pa"], r["integrator"], r["dt_s"] if r["integrator"] != "symplectic-euler" else "")

    configs = list(dict.fromkeys(config(r) for r in rows))
    index = {(r["tets"],) + config(r): r for r in rows}
    out = []
    for key in configs:
        e, integrator, dt = key
        step = "dt %.3g ms" % (1e3 * float(dt)) if dt else "0.9 x stable dt"
        label = '"E %.0e Pa\\n%s\\n%s"' % (float(e), integrator.replace("-euler", " Euler"), step)
        out.append([label] + [index[(str(t),) + key]["ms_per_simulated_s"] if (str(t),) + key in index else NAN
                              for t in tets])
    write(data, "soft.dat", ["config"] + ["t%d" % t for t in tets], out)
    with open(os.path.join(data, "soft_tets.txt"), "w") as f:
        f.write(" ".join(str(t) for t in tets))

    # The report's plots (issue 36). Section 2: the torque-free box's orientation error against the
    # wall time of a run, one block per integrator (gnuplot's `index`), in the CSV's order.
    rows = [r for r in read_csv(os.path.join(results, "accuracy.csv")) if r["case"] == "torque-free-box"]
    names = list(dict.fromkeys(r["integrator"] for r in rows))
    with open(os.path.join(data, "accuracy.dat"), "w") as f:
        f.write("# wall_ms_per_run orient_err_max_early_rad orient_err_max_rad steps_per_s, one block per integrator\n")
        for name in names:
            f.write("# %s\n" % name)
            for r in rows:
                if r["integrator"] == name:
                    f.write("%s %s %s %s\n" % (r["wall_ms_per_run"], r["orient_err_max_early_rad"],
                                               r["orient_err_max_rad"], r["steps_per_s"]))
            f.write("\n\n")
    with open(os.path.join(data, "accuracy_names.txt"), "w") as f:
        f.write(" ".join(names))
    with open(os.path.join(data, "accuracy_horizons.txt"), "w") as f:
        f.write("%s %s" % (rows[0]["early_horizon_s"], rows[0]["sim_time_s"]))
    with open(os.path.join(data, "accuracy_steps.txt"), "w") as f:
        f.write(", ".join("1/" + rate for rate in dict.fromkeys(r["steps_per_s"] for r in rows)))

    # Section 4: CPU time per narrow-phase query of each pair type, cheapest first (drawn at the bottom).
    gb = GoogleBenchmark(os.path.join(results, "narrowphase.csv"))
    pairs = [("SpherePlane", "sphere-plane"), ("CapsulePlane", "capsule-plane"), ("BoxPlane", "box-plane"),
             ("SphereSphere", "sphere-sphere"), ("SphereCapsule", "sphere-capsule"),
             ("CapsuleCapsule", "capsule-capsule"), ("SphereBox", "sphere-box"), ("CapsuleBox", "capsule-box"),
             ("BoxBoxSat", "box-box, SAT"), ("HullHullClimb", "hull-hull, climbing"),
             ("HullHullScan", "hull-hull, scanning")]
    costs = sorted((1e9 * gb.seconds("BM_" + key), label) for key, label in pairs)
    write(data, "narrowphase.dat", ["pair", "ns_per_query"], [['"%s"' % label, "%.6g" % ns] for ns, label in costs])

    # Section 5: the stacks of bench/contact_scenes.cpp, how far the box that moved most ended
    # from its start after 10 s, per solver (soft step's rows are the same with every integrator).
    rows = read_csv(os.path.join(results, "contact_scenes.csv"))
    index = by_keys(rows, "scene", "solver", "integrator")
    labels = {"stack10": "column 10", "stack20": "column 20", "stack40": "column 40", "pyramid20": "pyramid 210"}
    columns = [("soft-step", "expmap"), ("pgs", "expmap"), ("pgs", "dlm")]
    scenes = [s for s in labels if any(r["scene"] == s for r in rows)]
    if not scenes:
        raise MissingData("contact_scenes.csv: none of the scenes " + " ".join(labels))
    write(data, "stacks.dat", ["scene"] + ["%s-%s" % c for c in columns],
          [['"%s"' % labels[s]] + [index[(s,) + c]["farthest_m"] if (s,) + c in index else NAN for c in columns]
           for s in scenes])


if __name__ == "__main__":
    main()
