"""Reading the benchmark CSVs of bench/results/ (issue 11), shared by plot_data.py and
fill_report.py. Every accessor fails loudly (MissingData) when a file, a row or a column is absent:
a figure is never filled from stale or guessed numbers."""
import csv
import re
import os

TIME_UNIT_SECONDS = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}


class MissingData(Exception):
    pass


def read_csv(path):
    """The rows of a CSV file as dicts; MissingData when the file is absent or has no rows."""
    if not os.path.exists(path):
        raise MissingData("missing " + path)
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise MissingData("no rows in " + path)
    return rows


class GoogleBenchmark:
    """A Google Benchmark CSV (--benchmark_out_format=csv): one row per run, or per aggregate when
    repetitions were asked for; the median is taken when there are aggregates."""

    def __init__(self, path):
        self.path = path
        self.rows = {}
        for row in read_csv(path):
            name = row["name"]
            if row.get("error_occurred") == "true":
                continue
            for suffix in ("_mean", "_stddev", "_cv"):
                if name.endswith(suffix):
                    break
            else:
                # A run with a fixed iteration count carries it in its name ("/iterations:1").
                self.rows[re.sub(r"/iterations:\d+", "", name.removesuffix("_median"))] = row
        self.repetitions = any(r["name"].endswith("_median") for r in read_csv(path))

    def row(self, name):
        for candidate in (name, name + "/manual_time", name + "/real_time"):
            if candidate in self.rows:
                return self.rows[candidate]
        raise MissingData("%s: no run named %s" % (self.path, name))

    def has(self, name):
        try:
            self.row(name)
            return True
        except MissingData:
            return False

    def value(self, name, column):
        row = self.row(name)
        text = row.get(column, "")
        if text in ("", None):
            raise MissingData("%s: run %s has no %s" % (self.path, name, column))
        return float(text)

    def seconds(self, name, column="cpu_time"):
        """Time per iteration in seconds (cpu_time, or real_time for runs that use it)."""
        return self.value(name, column) * TIME_UNIT_SECONDS[self.row(name)["time_unit"]]


def by_keys(rows, *keys):
    """Index rows by a tuple of columns."""
    return {tuple(r[k] for k in keys): r for r in rows}
