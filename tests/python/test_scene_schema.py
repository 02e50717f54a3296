"""The JSON Schema of scene files (docs/scene.schema.json, `rbsim schema`), generated from the
parser's key tables (engine/include/rbsim/scene/scene_keys.h): the committed file is the
generator's output, every shipped scene passes it, the bad-input cases whose fault is a key, a type
or a range fail it, and the parser refuses what the schema's types and ranges refuse."""
import copy
import json
import re
import subprocess

import jsonschema
import pytest

from conftest import SCENES, SOURCE

SCHEMA_FILE = SOURCE / "docs" / "scene.schema.json"
BAD = SOURCE / "tests" / "data" / "bad"

# Bad-input cases (tests/data/bad/cases.json) that run a scene the schema passes: their fault lies
# past what a schema of keys, types and ranges can say. Each is here for the reason on its line;
# the test below asserts this is exactly the set, so a case the schema starts (or stops) catching
# shows up.
SCHEMA_CANNOT_CATCH = {
    # the contents of files the scene names
    "missing_mesh", "open_mesh_exact", "inverted_mesh", "empty_mesh", "not_obj_mesh", "mesh_is_folder",
    "two_corner_face", "index_out_of_range", "self_crossing_face", "zero_volume_mesh", "flat_mesh", "huge_mesh",
    "huge_scale", "infinite_vertex", "hull_inward", "hull_flat", "fracture_not_convex", "fracture_cube_inertia",
    "sdf_open_mesh", "mesh_dev_zero", "mesh_short_vertex", "mesh_word_coordinate", "mesh_word_face_index",
    "mesh_face_256_corners", "mesh_crosses_itself", "mesh_name_nul",
    # one key against another: mass or density, shape or shapes, start before end, [lo, hi] in order,
    # a tube thinner than its ring, a body or a ragdoll, a period's companions, a solver's joints
    "mass_and_density", "missing_shape", "force_ends_before_start", "particle_lifetime_reversed", "torus_fat_tube",
    "implicit_torus_fat_tube", "implicit_missing_parameter", "implicit_sdf_resolution", "static_and_kinematic",
    "motion_and_velocity", "drift_correction_without_matrix", "joint_limits_reversed", "joint_under_pgs",
    "spawn_body_and_ragdoll", "spawn_lifetime_at_load",
    # a vector's or a sum's length, a rotation, a direction's being non-zero, an offset n . p overflowing
    "non_unit_quaternion", "non_orthonormal_matrix", "mirror_matrix", "zero_quaternion", "normalize_reflection",
    "huge_rotation_matrix", "joint_zero_axis", "spawn_region_plus_offset", "fracture_plane_offset_overflow",
    # bodies named elsewhere in the file, and the names spawners and ragdolls make
    "no_bodies", "joint_names_bone", "joint_unknown_body", "joint_static_body_a", "joint_same_body",
    "spawner_makes_a_listed_name", "ragdoll_spawner_makes_a_listed_name", "ragdoll_spawner_makes_a_bone_name",
    "two_spawners_of_one_name", "ragdoll_takes_a_body_name", "sdf_slice_no_grid", "sdf_slice_offset_outside",
    # budgets and physics: work, steps, mass scale, overflow, geometry, a diverging run
    "absurd_duration", "duration_no_step", "mass_too_small_for_size", "mass_too_large", "body_too_large",
    "spring_force_overflow", "overflowing_force", "spawned_vertices_count_bones", "pivot_faster_than_light",
    "keyframes_faster_than_light", "keyframes_loop_jump", "fracture_planes_miss", "fracture_too_many_pieces",
    "particle_cloth_diverges", "soft_inverts", "csg_too_deep", "csg_empty_difference", "csg_empty_intersection",
    "implicit_resolution_budget", "implicit_csg_grids_over_budget", "implicit_mesh_over_budget", "sdf_resolution_budget",
    "sdf_sample_budget", "ragdoll_mass_tiny", "spawn_period_below_dt", "spawn_ragdoll_budget", "spawn_vertex_budget",
    "boxes_piled_at_one_point",
    # blocks whose keys have no types in a table yet (particles, soft bodies, planar, a comparison's values)
    "particle_unknown_emitter", "particle_negative_drag_flag", "particle_mass_inverse_overflow", "flock_budget",
    "soft_incompressible", "soft_unknown_model", "soft_cells_fraction", "soft_volume_underflow", "soft_modulus_range",
    "soft_resolution_budget", "planar_self_intersecting", "planar_area_overflow", "planar_diverges",
    "compare_bad_value", "compare_one_value", "compare_set_of_compared_key",
    # a duplicate key: JSON readers (and so a schema) see only one of the two
    "duplicate_key", "set_duplicate_key",
}


def generated(rbsim_binary):
    done = subprocess.run([rbsim_binary, "schema"], capture_output=True, text=True, timeout=60, check=True)
    return done.stdout


@pytest.fixture(scope="module")
def schema():
    with open(SCHEMA_FILE) as f:
        document = json.load(f)
    jsonschema.Draft202012Validator.check_schema(document)
    return document


@pytest.fixture(scope="module")
def validator(schema):
    return jsonschema.Draft202012Validator(schema)


def test_committed_schema_is_the_generators_output(rbsim_binary):
    with open(SCHEMA_FILE) as f:
        committed = f.read()
    assert committed == generated(rbsim_binary), "docs/scene.schema.json is stale: build/rbsim schema > docs/scene.schema.json"


def test_schema_refuses_unknown_keys_where_the_parser_does(schema):
    props = schema["properties"]
    assert schema["additionalProperties"] is False
    for block in ("world", "view", "kill_volume", "compare"):
        assert props[block]["additionalProperties"] is False, block
    for block in ("bodies", "planes", "spawn", "joints", "ragdolls"):
        assert props[block]["items"]["additionalProperties"] is False, block
    # A sphere takes a radius, not extents: the per-type keys are the parser's allowOnly lists.
    shape = props["bodies"]["items"]["properties"]["shape"]
    sphere = next(c["then"] for c in shape["allOf"] if c["if"]["properties"]["type"]["const"] == "sphere")
    assert set(sphere["properties"]) == {"type", "radius"}
    assert sphere["additionalProperties"] is False


def shipped_scenes():
    scenes = sorted(SCENES.rglob("*.json")) + sorted((SOURCE / "tests" / "data" / "window").glob("*.json"))
    assert len(scenes) > 40
    return scenes


@pytest.mark.parametrize("path", shipped_scenes(), ids=lambda p: str(p.relative_to(SOURCE)))
def test_every_shipped_scene_validates(validator, path):
    with open(path) as f:
        document = json.load(f)
    errors = [f"{'/'.join(map(str, e.absolute_path))}: {e.message}" for e in validator.iter_errors(document)]
    assert not errors, errors


def refuse(text):
    raise ValueError(f"{text} is not a JSON number")


def finite(text):
    """A JSON number as rbsim reads it: 1e999 is no double, an error before any key is read."""
    value = float(text)
    if value in (float("inf"), float("-inf")):
        raise ValueError(f"{text} is too large for a double")
    return value


def apply_set(document, assignment):
    """--set key=value as engine/src/scene/override.cpp applies it; None when the path names nothing."""
    path, _, text = assignment.partition("=")
    parts = [p for p in re.split(r"[.\[\]]", path) if p]
    try:
        value = json.loads(text, parse_constant=refuse, parse_float=finite)
    except ValueError:
        value = text  # a bare word (and NaN, which is no JSON number) is a string
    node = document
    for i, part in enumerate(parts):
        last = i == len(parts) - 1
        if isinstance(node, list):
            index = int(part) if part.isdigit() else next((k for k, e in enumerate(node) if isinstance(e, dict) and e.get("name") == part), len(node))
            if index >= len(node):
                return None
            if last:
                node[index] = value
            else:
                node = node[index]
        elif isinstance(node, dict):
            if last:
                node[part] = value
            else:
                node = node.setdefault(part, {})
        else:
            return None
    return document


def scene_case(case):
    """The scene document a `run` case hands the parser, or None when its fault is not in a scene
    (a flag, a device, an unreadable file)."""
    args = case["args"]
    if args[0] != "run" or len(args) < 2:
        return None
    if args[1].startswith("{dir}/") and args[1].endswith(".json"):
        path = BAD / args[1][len("{dir}/"):]
    else:
        path = SCENES / f"{args[1]}.json"
    flags = args[2:]
    sets = []
    while flags:
        if flags[0] == "--no-render":
            flags = flags[1:]
        elif flags[0] == "--set" and len(flags) > 1:
            sets.append(flags[1])
            flags = flags[2:]
        else:
            return None  # a flag's fault, or a run that renders
    try:
        with open(path) as f:
            document = json.load(f, parse_constant=refuse, parse_float=finite)
    except (OSError, ValueError):
        return None  # no scene to check: a missing file, a folder, a syntax error
    for assignment in sets:
        if "=" not in assignment or assignment.startswith(("[", "=")):
            return None
        try:
            document = apply_set(document, assignment)
        except ValueError:
            return None
        if document is None:
            return None
    return document


def test_bad_cases_fail_validation_unless_known(validator):
    with open(BAD / "cases.json") as f:
        cases = json.load(f)["cases"]
    passed_but_bad, refused_but_good, checked = set(), set(), 0
    for case in cases:
        document = scene_case(case)
        if document is None:
            continue
        checked += 1
        valid = validator.is_valid(document)
        if case.get("exit", 2) == 0 and not valid:
            refused_but_good.add(case["name"])
        if case.get("exit", 2) == 2 and valid:
            passed_but_bad.add(case["name"])
    assert checked > 150
    assert not refused_but_good, "scenes rbsim runs that the schema refuses"
    assert passed_but_bad - SCHEMA_CANNOT_CATCH == set(), "bad scenes the schema passes: add a key, type or range, or list them"
    assert SCHEMA_CANNOT_CATCH - passed_but_bad == set(), "listed as uncatchable but the schema now refuses them: remove them"


def test_wrong_key_type_and_range_cases_name_the_parsers_field(validator):
    # The schema's first error points where the parser's message does.
    with open(BAD / "cases.json") as f:
        cases = {c["name"]: c for c in json.load(f)["cases"]}
    for name, where in {"unknown_key": "bodies/0", "wrong_type": "bodies/0/mass", "zero_extent": "bodies/0/shape/extents/1",
                        "absurd_dt": "world/dt", "unknown_integrator": "world/integrator", "zero_substeps": "world/substeps",
                        "key_of_another_shape": "bodies/0/shape"}.items():
        errors = list(validator.iter_errors(scene_case(cases[name])))
        assert errors, name
        assert any("/".join(map(str, e.absolute_path)) == where for e in errors), (name, [list(e.absolute_path) for e in errors])


# The parser agrees with the schema's types and ranges: a value just past a bound, of the wrong
# type, or outside an enum is refused naming the key; each enum value is taken.
BASE = {"world": {"gravity": [0, -9.81, 0], "dt": 0.01, "duration": 0.02},
        "bodies": [{"name": "a", "shape": {"type": "box", "extents": [1, 1, 1]}, "mass": 1}]}


def past_bounds(sub):
    integer = sub.get("type") == "integer"
    step = lambda x: 1 if integer else max(abs(x), 1.0) * 1e-3
    out = []
    if "minimum" in sub:
        out.append(sub["minimum"] - step(sub["minimum"]))
    if "exclusiveMinimum" in sub:
        out.append(sub["exclusiveMinimum"])
    if "maximum" in sub:
        out.append(sub["maximum"] + step(sub["maximum"]))
    if "exclusiveMaximum" in sub:
        out.append(sub["exclusiveMaximum"])
    return out


def probes(schema, block):
    """(key, value, refused?) for every scalar key of the world or view block."""
    out = []
    for name, sub in schema["properties"][block]["properties"].items():
        if name == "steps":
            continue  # replaces duration; its bound is the positiveInt limit
        kind = sub.get("type")
        if kind in ("number", "integer"):
            out += [(name, v, True) for v in past_bounds(sub)] + [(name, "x", True)]
        elif kind == "boolean":
            out.append((name, 3, True))
        elif kind == "string" and "enum" in sub:
            out += [(name, "no-such-name", True)] + [(name, v, False) for v in sub["enum"]]
        elif kind == "array" and sub.get("items", {}).get("type") == "number" and sub.get("maxItems") == 3:
            out += [(name, [v, 0, 0], True) for v in past_bounds(sub["items"])] + [(name, [1, 2], True)]
    return out


@pytest.mark.parametrize("block", ["world", "view"])
def test_parser_refuses_what_the_schema_refuses(rbsim_binary, schema, validator, tmp_path, block):
    disagreements = []
    for name, value, refused in probes(schema, block):
        document = copy.deepcopy(BASE)
        document.setdefault(block, {})[name] = value
        if refused == validator.is_valid(document):
            disagreements.append((name, value, "schema"))
            continue
        if not refused and (block, name, value) in {("world", "solver", "pgs"), ("world", "solver", "lcp")}:
            document["world"]["friction"] = "cone"
        scene = tmp_path / "probe.json"
        scene.write_text(json.dumps(document))
        done = subprocess.run([rbsim_binary, "run", str(scene), "--no-render", "--quiet"], capture_output=True, text=True, timeout=60)
        if (done.returncode == 2) != refused or (refused and f"{block}.{name}" not in done.stderr):
            disagreements.append((name, value, done.returncode, done.stderr.strip()[-200:]))
    assert not disagreements
