#!/usr/bin/python3
"""Absurd-but-valid scenes: every number of the project's scenes replaced by extreme values.

Walks each source scene's JSON, and for every number (each element of number arrays too) writes a
variant with that one number replaced by 1e-300, -1e-300, 1e300, -1e300, 0, -0.0, 1e9, 1e-9 and -1
(integers also by 2^31, 2^63 and 2^64-1), then runs the real binary on it:

    rbsim run VARIANT --no-render --quiet [--set world.steps=N]

The steps override keeps runs short; it is left out when the swept key is itself a step count or
a duration, since those are what must be refused quickly with an estimate. A run FAILS when it is
killed by a signal (crash), exits with a code other than 0 or 2, outlives --timeout (a hang), or
exits 2 without "rbsim: error: FILE: FIELD: problem" naming a field (a divergence while running
is reported as its own class, since it names no field; --allow-diverged passes it). Keys that
differ only in the index of an array of objects (bodies[0..39].mass) are swept once, on the first
element, unless --every-element is given. Prints a summary table, writes the
failures (file, key path, value, exit or signal, last stderr line) to --out and exits 1 when any
run failed.

    /usr/bin/python3 tests/fuzz/absurd_scenes.py --binary build/rbsim            (every key)
    /usr/bin/python3 tests/fuzz/absurd_scenes.py --binary build/rbsim --small    (ctest)

Variants are written to a temporary folder that mirrors the source folder's parent with symbolic
links, so relative mesh paths ("../meshes/t_handle.obj") resolve as they do for the original.
"""
import argparse
import collections
import concurrent.futures
import json
import os
import random
import re
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import time

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
FLOAT_VALUES = [1e-300, -1e-300, 1e300, -1e300, 0, -0.0, 1e9, 1e-9, -1]
# Integer keys are counts or indices: huge counts on top of the above (as JSON integers).
INT_VALUES = [1000000000, 2**31, 2**63, 2**64 - 1]
SHORT_STEPS = 20              # steps of a shortened run: enough to step every stage a few times
TIME_KEYS = re.compile(r"(^|\.)(steps|duration)$")  # keys whose sweep must not be shortened
SMALL_RUNS = 150              # --small: runs, sampled evenly over files, keys and values
SMALL_SEED = 19               # --small: fixed so the ctest picks the same variants every time
FIELD = re.compile(r"^[A-Za-z_][\w\-]*(\[\d+\]|\.[\w\-]+)*$")


def default_sources():
    scenes = os.path.join(REPO, "assets", "scenes")
    files = sorted(os.path.join(scenes, f) for f in os.listdir(scenes) if f.endswith(".json"))
    return files + [os.path.join(REPO, "tests", "data", "bad", "valid.json")]


def leaves(node, path=()):
    """(path, value) of every number in the document, depth first."""
    if isinstance(node, dict):
        for key, child in node.items():
            yield from leaves(child, path + (key,))
    elif isinstance(node, list):
        for i, child in enumerate(node):
            yield from leaves(child, path + (i,))
    elif isinstance(node, (int, float)) and not isinstance(node, bool):
        yield path, node


def path_text(path):
    out = ""
    for part in path:
        out += "[%d]" % part if isinstance(part, int) else ("." if out else "") + part
    return out


def replaced(document, path, value):
    copy = json.loads(json.dumps(document))
    node = copy
    for part in path[:-1]:
        node = node[part]
    node[path[-1]] = value
    return copy


def value_text(value):
    return json.dumps(value)


def key_class(document, path):
    """The path with indices into arrays of objects (bodies[3], planes[1]) blanked: the 40 boxes of
    a stack have the same keys, and one of them stands for all unless --every-element is given."""
    out, node = [], document
    for part in path:
        blank = isinstance(part, int) and isinstance(node[part], (dict, list))
        out.append("*" if blank else part)
        node = node[part]
    return tuple(out)


def variants(sources, keys_regex, every_element):
    """Per source file: [(file, document, path, value)], every key and every value."""
    per_file = []
    for source in sources:
        with open(source) as f:
            document = json.load(f)
        items, seen = [], set()
        for path, original in leaves(document):
            key = path_text(path)
            if not every_element:
                cls = key_class(document, path)
                if cls in seen:
                    continue
                seen.add(cls)
            if keys_regex and not re.search(keys_regex, key):
                continue
            values = FLOAT_VALUES + (INT_VALUES if isinstance(original, int) else [])
            items.extend((source, document, path, v) for v in values)
        if items:
            per_file.append(items)
    return per_file


def sample(per_file, max_runs, seed):
    """Every variant, or max_runs of them spread evenly over files, keys and values."""
    rng = random.Random(seed)
    if max_runs is None or max_runs >= sum(len(items) for items in per_file):
        everything = [item for items in per_file for item in items]
        rng.shuffle(everything)  # so that a sweep stopped early has covered every file
        return everything
    # Files take turns; within a file the keys come in a shuffled order (again and again); the
    # value is the next one of a cursor shared by every pick, so the values are spread evenly.
    files = []
    for items in per_file:
        by_key = collections.OrderedDict()
        for item in items:
            by_key.setdefault(item[2], []).append(item)
        keys = list(by_key)
        rng.shuffle(keys)
        files.append((keys, by_key))
    picked, used, cursor, turn = [], set(), 0, 0
    while len(picked) < max_runs:
        keys, by_key = files[turn % len(files)]
        key = keys[(turn // len(files)) % len(keys)]
        turn += 1
        choices = [item for item in by_key[key] if id(item) not in used]
        if not choices:
            continue
        item = choices[cursor % len(choices)]
        cursor += 1
        used.add(id(item))
        picked.append(item)
    return picked


class Mirror:
    """A temporary copy of a source folder's surroundings: the folder's parent's entries linked,
    the folder itself a real directory (its files linked) where the variants are written."""

    def __init__(self, root):
        self.root = root
        self.dirs = {}

    def folder(self, source_dir):
        if source_dir not in self.dirs:
            base = os.path.join(self.root, "m%d" % len(self.dirs))
            os.makedirs(base)
            parent = os.path.dirname(source_dir)
            for entry in os.listdir(parent):
                if os.path.join(parent, entry) != source_dir:
                    os.symlink(os.path.join(parent, entry), os.path.join(base, entry))
            mine = os.path.join(base, os.path.basename(source_dir))
            os.makedirs(mine)
            for entry in os.listdir(source_dir):
                os.symlink(os.path.join(source_dir, entry), os.path.join(mine, entry))
            self.dirs[source_dir] = mine
        return self.dirs[source_dir]


def limit_memory(limit_bytes):
    def apply():
        # 0: no address-space limit (AddressSanitizer reserves terabytes of shadow address space).
        if limit_bytes > 0:
            resource.setrlimit(resource.RLIMIT_AS, (limit_bytes, limit_bytes))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
    return apply


def classify(returncode, stderr, timed_out):
    """(failure class or None, detail)."""
    lines = [line for line in stderr.splitlines() if line.strip()]
    last = lines[-1] if lines else ""
    if timed_out:
        return "hang", last
    if returncode < 0:
        name = signal.Signals(-returncode).name if -returncode in signal.Signals._value2member_map_ else str(-returncode)
        return "signal " + name, last
    if returncode == 0:
        return None, last
    if returncode != 2:
        return "exit %d" % returncode, last
    error = next((line for line in lines if line.startswith("rbsim: error: ")), None)
    if error is None:
        return "exit 2 without 'rbsim: error:'", last
    rest = error[len("rbsim: error: "):]
    if rest.startswith("the simulation diverged"):
        return "exit 2 diverged (no field)", error
    parts = rest.split(": ")
    # FILE: FIELD: problem (the file may be "command line" for flags).
    if len(parts) < 3 or not FIELD.match(parts[1]):
        return "exit 2 without a field path", error
    return None, error


def run_one(args, mirror, index, item, deadline):
    if deadline is not None and time.monotonic() > deadline:
        return None  # out of time: not run, not counted
    source, document, path, value = item
    key = path_text(path)
    folder = mirror.folder(os.path.dirname(os.path.abspath(source)))
    variant = os.path.join(folder, ".absurd_%d_%s" % (index, os.path.basename(source)))
    with open(variant, "w") as f:
        json.dump(replaced(document, path, value), f)
    command = [args.binary, "run", variant, "--no-render", "--quiet"]
    if not TIME_KEYS.search(key):
        command += ["--set", "world.steps=%d" % SHORT_STEPS]
    started = time.monotonic()
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                               preexec_fn=limit_memory(args.memory_mb << 20), start_new_session=True)
    timed_out = False
    try:
        _, err = process.communicate(timeout=args.timeout)
    except subprocess.TimeoutExpired:
        timed_out = True
        os.killpg(process.pid, signal.SIGKILL)
        _, err = process.communicate()
    seconds = time.monotonic() - started
    stderr = err.decode("utf-8", "replace")
    failure, detail = classify(process.returncode, stderr, timed_out)
    if failure and failure.startswith("exit 2 diverged") and args.allow_diverged:
        failure = None
    if failure is None:
        os.unlink(variant)
    return {
        "file": os.path.relpath(source, REPO), "key": key, "value": value_text(value),
        "exit": process.returncode, "failure": failure, "detail": detail.strip()[:600],
        "seconds": round(seconds, 2), "command": command, "variant": variant,
    }


def root_cause(result):
    """Failures with the same class and the same message (numbers and paths blanked) share a cause."""
    message = re.sub(r"\S*\.absurd_\d+_", "", result["detail"])
    message = re.sub(r"-?\d[\d.e+\-]*", "N", message)
    message = re.sub(r"'[^']*'", "'X'", message)  # body and system names
    if result["failure"].startswith("exit 2 diverged"):
        message = message.split(" (")[0]  # what stopped being finite, not the state dump after it
    if result["failure"].startswith(("signal", "hang")):
        # A crash or a hang says little on stderr: the key that caused it tells causes apart.
        message += " [key %s]" % re.sub(r"\[\d+\]", "", result["key"])
    return result["failure"], message


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--binary", default=os.path.join(REPO, "build", "rbsim"))
    parser.add_argument("--sources", nargs="*", help="scene files (default: assets/scenes/*.json and tests/data/bad/valid.json)")
    parser.add_argument("--max-runs", type=int, help="at most this many variants, sampled evenly")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--keys-regex", help="only keys whose path (e.g. bodies[0].mass) matches")
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--timeout", type=float, default=20.0, help="seconds per run before it counts as a hang")
    parser.add_argument("--max-seconds", type=float, help="start no run after this many seconds (the report covers the runs done)")
    parser.add_argument("--memory-mb", type=int, default=4096, help="address-space limit per run (0: none, for sanitizer builds)")
    parser.add_argument("--out", default="absurd_report.md", help="report file (default: %(default)s)")
    parser.add_argument("--allow-diverged", action="store_true",
                        help="count exit 2 'the simulation diverged' as a pass (by default it fails: it names no field)")
    parser.add_argument("--every-element", action="store_true",
                        help="sweep every element of arrays of objects (bodies[0..n]), not the first of each key")
    parser.add_argument("--keep", help="copy the failing variants into this folder")
    parser.add_argument("--small", action="store_true", help="the ctest mode: --max-runs %d (unless given) --seed %d" % (SMALL_RUNS, SMALL_SEED))
    args = parser.parse_args()
    if args.small:
        args.max_runs, args.seed = args.max_runs or SMALL_RUNS, SMALL_SEED  # --max-runs may shorten it
    if not os.access(args.binary, os.X_OK):
        sys.exit("absurd_scenes.py: no executable binary at %s (build the rbsim target)" % args.binary)

    picked = sample(variants(args.sources or default_sources(), args.keys_regex, args.every_element), args.max_runs, args.seed)
    scratch = tempfile.mkdtemp(prefix="rbsim-absurd-")
    mirror = Mirror(scratch)
    for source in {item[0] for item in picked}:
        mirror.folder(os.path.dirname(os.path.abspath(source)))  # created before the threads start
    started = time.monotonic()
    deadline = started + args.max_seconds if args.max_seconds else None
    results = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = [pool.submit(run_one, args, mirror, i, item, deadline) for i, item in enumerate(picked)]
        for future in concurrent.futures.as_completed(futures):
            result = future.result()
            if result is None:
                continue
            results.append(result)
            if len(results) % 250 == 0:
                print("... %d of %d runs, %d failed" % (len(results), len(picked),
                                                       sum(1 for r in results if r["failure"])), flush=True)
            if result["failure"]:
                print("FAIL %-32s %s = %s: %s: %s" % (result["failure"], result["file"], result["key"],
                                                     result["value"], result["detail"][:240]), flush=True)
    wall = time.monotonic() - started
    results.sort(key=lambda r: (r["file"], r["key"], r["value"]))
    failures = [r for r in results if r["failure"]]

    # Summary: per value, how the runs ended.
    outcomes = collections.defaultdict(collections.Counter)
    for r in results:
        outcomes[r["value"]]["exit 0" if r["exit"] == 0 and not r["failure"] else
                             "exit 2" if not r["failure"] else "FAIL"] += 1
    print("\n%-24s %8s %8s %8s" % ("value", "exit 0", "exit 2", "FAIL"))
    for value in sorted(outcomes, key=lambda v: json.loads(v)):
        c = outcomes[value]
        print("%-24s %8d %8d %8d" % (value, c["exit 0"], c["exit 2"], c["FAIL"]))
    by_class = collections.Counter(r["failure"] for r in failures)
    causes = collections.OrderedDict()
    for r in failures:
        causes.setdefault(root_cause(r), []).append(r)
    if len(results) < len(picked):
        print("\n--max-seconds %g reached: %d of %d variants not run" % (args.max_seconds, len(picked) - len(results), len(picked)))
    print("\n%d runs in %.0f s, %d failures in %d classes, %d distinct causes" %
          (len(results), wall, len(failures), len(by_class), len(causes)))
    for name, count in by_class.most_common():
        print("  %5d  %s" % (count, name))

    out = args.out
    with open(out, "w") as f:
        f.write("# absurd_scenes.py: %d runs, %d failures, %d distinct causes\n\n" % (len(results), len(failures), len(causes)))
        f.write("command: %s\n\n" % " ".join(sys.argv))
        for (name, message), group in causes.items():
            first = group[0]
            f.write("## %s (%d runs)\n\n%s\n\n" % (name, len(group), first["detail"] or "(no stderr)"))
            for r in group[:12]:
                f.write("- %s: `%s` = %s -> exit %s, %.1f s: %s\n" % (r["file"], r["key"], r["value"], r["exit"],
                                                                   r["seconds"], r["detail"][:240]))
            if len(group) > 12:
                f.write("- ... and %d more\n" % (len(group) - 12))
            f.write("\n")
        f.write("## all failures (json lines)\n\n")
        for r in failures:
            f.write(json.dumps({k: r[k] for k in ("file", "key", "value", "exit", "failure", "detail", "seconds")}) + "\n")
    # Every run, failed or not, for questions the table does not answer (which absurd values were
    # accepted with exit 0, which field a refusal named).
    with open(os.path.splitext(out)[0] + ".jsonl", "w") as f:
        for r in results:
            f.write(json.dumps({k: r[k] for k in ("file", "key", "value", "exit", "failure", "detail", "seconds")}) + "\n")
    if args.keep:
        os.makedirs(args.keep, exist_ok=True)
        for r in failures:
            shutil.copy(r["variant"], os.path.join(args.keep, os.path.basename(r["variant"])))
    shutil.rmtree(scratch, ignore_errors=True)
    print("report: %s" % out)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
