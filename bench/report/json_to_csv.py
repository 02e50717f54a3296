"""Google Benchmark JSON (--benchmark_out_format=json) to CSV (issue 11). Its own CSV reporter
aborts when runs of one program have different counters (step_bench, broadphase_bench, ...), so
the programs write JSON and this writes the CSV, one row per run or aggregate, with the union of
the counters as columns (empty where a run has none).

usage: python3 bench/report/json_to_csv.py IN.json OUT.csv
"""
import csv
import json
import sys

FIXED = ["name", "iterations", "real_time", "cpu_time", "time_unit", "bytes_per_second", "items_per_second",
         "label", "error_occurred", "error_message"]
NOT_COUNTERS = set(FIXED) | {"family_index", "per_family_instance_index", "run_name", "run_type", "repetitions",
                             "repetition_index", "threads", "aggregate_name", "aggregate_unit"}


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: json_to_csv.py IN.json OUT.csv")
    with open(sys.argv[1]) as f:
        runs = json.load(f)["benchmarks"]
    if not runs:
        sys.exit("json_to_csv.py: no runs in " + sys.argv[1])
    counters = list(dict.fromkeys(k for r in runs for k in r if k not in NOT_COUNTERS))
    with open(sys.argv[2], "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(FIXED + counters)
        for r in runs:
            row = [r.get(k, "") for k in FIXED + counters]
            row[FIXED.index("error_occurred")] = "true" if r.get("error_occurred") else "false"
            writer.writerow(row)


if __name__ == "__main__":
    main()
