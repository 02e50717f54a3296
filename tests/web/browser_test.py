#!/usr/bin/python3
"""The browser build in a real browser (issue 59): Debian's chromium, headless, driven through
chromium-driver (python3-selenium), over the built site served by Python's http.server.

For each scene it loads web/pages/embed.html paused, steps the World 120 times through the page's
JavaScript hook (window.rbsimHook), and checks
  - every body's x and q against the native program's trace of the same scene (rbsim run SCENE
    --trace), bit for bit;
  - that the canvas shows the bodies: the pixel at the centre of body 0's largest triangle facing
    the camera is not the background;
then, on one scene, drags a body with the mouse (press on it, move, release) and checks that it
followed the pointer.

    /usr/bin/python3 tests/web/browser_test.py --site build-web/site --rbsim build/rbsim [SCENE ...]

Exit 0 when every check holds, 1 otherwise (each failure printed), 2 on bad arguments or a
missing browser.
"""
import argparse
import csv
import functools
import http.server
import os
import shutil
import subprocess
import sys
import tempfile
import threading

STEPS = 120
# The scenes of demos 1 to 8 that hold one World (the others compare several side by side, which
# the JavaScript API does not build yet), and the two stacks the issue times.
DEFAULT_SCENES = [
    "assignment2_a_manual_pose", "assignment2_b_velocity", "assignment2_c_force_at_point",
    "assignment2_d_mesh_inertia", "assignment2_f_joints", "contact_response", "contact_stacking",
    "narrowphase_pairs", "machinery_washer", "round_shapes", "rounded_boxes", "sdf_pour",
    "soft_bars", "tunnelling_on",
]
DRAG_SCENE = "contact_response"
BACKGROUND = (0xdf, 0xe6, 0xee)  # embed.html's canvas background


def native_trace(rbsim, scene, folder):
    """{step: [(x, y, z, qw, qx, qy, qz) per body]} from the native program's trace."""
    path = os.path.join(folder, scene + ".csv")
    subprocess.run([rbsim, "run", scene, "--steps", str(STEPS), "--trace", path, "--no-render", "--quiet"], check=True)
    steps = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            steps.setdefault(int(row["step"]), []).append(tuple(float(row[k]) for k in ("x", "y", "z", "qw", "qx", "qy", "qz")))
    return steps


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


def serve(site):
    handler = functools.partial(QuietHandler, directory=site)
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server


def browser():
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    options = webdriver.ChromeOptions()
    options.binary_location = "/usr/bin/chromium"
    for flag in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--window-size=900,700"):
        options.add_argument(flag)
    return webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)


# Waits for the page's World, then runs `body` with it as `world`; returns what `body` returns.
READY = """
const done = arguments[arguments.length - 1];
window.rbsimHook.ready.then((world) => { try { done((function (world) { %s })(world)); }
                                         catch (e) { done({error: String(e.message || e)}); } },
                            (e) => done({error: String(e.message || e)}));
"""


def check_scene(driver, url, scene, trace, failures):
    driver.get(f"{url}/embed.html?scene={scene}&paused=1")
    result = driver.execute_async_script(READY % f"""
        world.step({STEPS});
        window.rbsimHook.show();
        const x = Array.from(world.positions(), String), q = Array.from(world.orientations(), String);
        // The centroid of body 0's largest triangle facing the camera (as the page culls them):
        // a point the page fills, with body 0's colour or that of a body in front of it.
        const camera = window.rbsimHook.camera();
        const p = world.vertices(0), t = world.triangles(0);
        let centre = null, largest = 0;
        for (let k = 0; k < t.length; k += 3) {{
          const [a, b, c] = [t[k], t[k + 1], t[k + 2]].map((v) => camera.project(p[3 * v], p[3 * v + 1], p[3 * v + 2]));
          const facing = -((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
          if (a[2] > 0 && b[2] > 0 && c[2] > 0 && facing > largest) {{
            largest = facing;
            centre = [(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3];
          }}
        }}
        if (!centre) return {{error: "body 0 has no triangle facing the camera"}};
        const canvas = document.getElementById("view");
        const pixel = Array.from(canvas.getContext("2d").getImageData(Math.round(centre[0]), Math.round(centre[1]), 1, 1).data);
        return {{x, q, pixel, steps: world.stepCount()}};""")
    if "error" in result:
        failures.append(f"{scene}: the page failed: {result['error']}")
        return
    expected = trace[STEPS]
    n = len(result["x"]) // 3
    if n != len(expected):
        failures.append(f"{scene}: {n} bodies in the page, {len(expected)} in the native trace")
        return
    for i in range(n):
        ours = tuple(float(v) for v in result["x"][3 * i:3 * i + 3] + result["q"][4 * i:4 * i + 4])
        if ours != expected[i]:
            failures.append(f"{scene}: body {i} after {STEPS} steps: page {ours}, native {expected[i]}")
            return
    if tuple(result["pixel"][:3]) == BACKGROUND or result["pixel"][3] == 0:
        failures.append(f"{scene}: the canvas shows background {result['pixel']} on body 0's largest facing triangle")
        return
    print(f"browser_test: {scene}: {n} bodies equal the native trace bit for bit after {STEPS} steps; "
          f"body 0 drawn (pixel {result['pixel'][:3]})")


def check_drag(driver, url, failures):
    """Presses on body 1 of DRAG_SCENE, moves the pointer 120 px up and holds it there for 60
    frames, releases: the body must have risen and the drag spring be gone."""
    from selenium.webdriver.common.action_chains import ActionChains
    driver.get(f"{url}/embed.html?scene={DRAG_SCENE}&paused=1")
    before = driver.execute_async_script(READY % """
        const i = 1, x = world.positions();
        const p = window.rbsimHook.camera().project(x[3 * i], x[3 * i + 1], x[3 * i + 2]);
        const box = document.getElementById("view").getBoundingClientRect();
        return {y: x[3 * i + 1], px: p[0] * box.width / 800 - box.width / 2, py: p[1] * box.height / 500 - box.height / 2};""")
    if "error" in before:
        failures.append(f"drag: the page failed: {before['error']}")
        return
    canvas = driver.find_element("id", "view")
    actions = ActionChains(driver)
    actions.move_to_element_with_offset(canvas, int(before["px"]), int(before["py"])).click_and_hold()
    actions.move_by_offset(0, -120).perform()
    grabbed = driver.execute_script("return window.rbsimHook.world.grabbed();")
    driver.execute_script("const w = window.rbsimHook.world; for (let k = 0; k < 60; ++k) w.step(1);")
    ActionChains(driver).release().perform()
    after = driver.execute_script("const w = window.rbsimHook.world; return {y: w.positions()[4], grabbed: w.grabbed()};")
    if grabbed != 1:
        failures.append(f"drag: pressing on body 1 grabbed body {grabbed}")
    elif not after["y"] > before["y"] + 0.05:
        failures.append(f"drag: body 1 did not follow the pointer up: y {before['y']} -> {after['y']}")
    elif after["grabbed"] != -1:
        failures.append("drag: releasing the mouse left the drag on")
    else:
        print(f"browser_test: drag: body 1 of {DRAG_SCENE} followed the pointer from y = {before['y']:.3f} m to {after['y']:.3f} m, "
              "and let go on release")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--site", required=True, help="the built site (build-web/site)")
    parser.add_argument("--rbsim", required=True, help="the native program, for the traces")
    parser.add_argument("scenes", nargs="*", default=DEFAULT_SCENES)
    args = parser.parse_args()
    for path, what in ((os.path.join(args.site, "rbsim.js"), "the site"), (args.rbsim, "the native program"),
                       ("/usr/bin/chromium", "chromium"), ("/usr/bin/chromedriver", "chromium-driver")):
        if not os.path.exists(path):
            print(f"browser_test: {what} is missing: {path}", file=sys.stderr)
            return 2
    server = serve(args.site)
    url = f"http://127.0.0.1:{server.server_address[1]}"
    failures = []
    folder = tempfile.mkdtemp(prefix="rbsim-browser-")
    driver = browser()
    try:
        driver.set_script_timeout(120)
        for scene in args.scenes:
            check_scene(driver, url, scene, native_trace(args.rbsim, scene, folder), failures)
        check_drag(driver, url, failures)
    finally:
        driver.quit()
        server.shutdown()
        shutil.rmtree(folder)
    for failure in failures:
        print(f"browser_test: FAILED: {failure}", file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
