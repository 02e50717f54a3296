#!/usr/bin/python3
"""What a frame of the browser build costs in headless chromium (issue 59: 60 frames per second
on demo 2's and demo 5's scenes): the example page (web/pages/embed.html) of each scene, paused,
then FRAMES frames of one step and one redraw each, timed inside the page with performance.now().
Prints, for each scene, the mean frame in ms (step and draw apart; performance.now() is coarse in
a page, ~0.1 ms, so means over all frames, not medians of each), the slowest frame, and the frames
per second the mean allows; a frame fits 60 per second in 16.7 ms.

    /usr/bin/python3 bench/web_frame_time.py --site build-web/site [SCENE ...]

Needs chromium, chromium-driver and python3-selenium (.ci/web installs them).
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "web"))
import browser_test  # noqa: E402  (the server and browser set-up)

FRAMES = 300
# Demo 2's free flight and joints, demo 5's stacks (a column of 10 and a pyramid of 55, and the
# 218-body washer of demo 8 for scale).
DEFAULT_SCENES = ["assignment2_b_velocity", "assignment2_f_joints", "contact_stacking", "contact_response", "machinery_washer"]

TIMED = """
const step = [], draw = [];
for (let k = 0; k < %d; ++k) {
  const t0 = performance.now();
  world.step(1);
  const t1 = performance.now();
  window.rbsimHook.show();
  const t2 = performance.now();
  step.push(t1 - t0);
  draw.push(t2 - t1);
}
return {step, draw, bodies: world.bodyCount()};
"""


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--site", required=True)
    parser.add_argument("scenes", nargs="*", default=DEFAULT_SCENES)
    args = parser.parse_args()
    server = browser_test.serve(args.site)
    url = f"http://127.0.0.1:{server.server_address[1]}"
    driver = browser_test.browser()
    driver.set_script_timeout(600)
    try:
        print(f"{'scene':<24} {'bodies':>6} {'step ms':>8} {'draw ms':>8} {'frame ms':>9} {'slowest':>8} {'fps':>6}")
        for scene in args.scenes:
            driver.get(f"{url}/embed.html?scene={scene}&paused=1")
            r = driver.execute_async_script(browser_test.READY % (TIMED % FRAMES))
            if "error" in r:
                print(f"{scene}: {r['error']}", file=sys.stderr)
                return 1
            frames = [s + d for s, d in zip(r["step"], r["draw"])]
            m = sum(frames) / len(frames)
            print(f"{scene:<24} {r['bodies']:>6} {sum(r['step']) / FRAMES:8.3f} {sum(r['draw']) / FRAMES:8.3f} {m:9.3f} "
                  f"{max(frames):8.2f} {1000.0 / m:6.0f}")
    finally:
        driver.quit()
        server.shutdown()
    return 0


if __name__ == "__main__":
    sys.exit(main())
