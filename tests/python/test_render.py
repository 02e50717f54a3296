"""Frames from Python are the program's frames; clips are written by the program's writer; the depth
and segmentation images (issue 57) against projective geometry."""
import glob
import json
import subprocess

import matplotlib.image as mpimg
import numpy as np
import pytest
import rbsim

from conftest import SCENES, SOURCE, run_cli

W, H = 320, 180


def test_frames_equal_the_programs_png_frames(rbsim_binary, tmp_path):
    overrides = ["world.steps=24", "view.fps=30", f"view.size=[{W},{H}]"]
    args = ["run", str(SCENES / "round_shapes.json"), "--frames", str(tmp_path), "--quiet"]
    code, err = run_cli(rbsim_binary, *args, *[a for o in overrides for a in ("--set", o)])
    assert code == 0, err
    pngs = sorted(glob.glob(str(tmp_path / "frame_*.png")))
    scene = rbsim.load_scene(str(SCENES / "round_shapes.json"), overrides)
    world = scene.world()
    steps_per_frame = round(1 / 30 / world.dt)
    renderer = rbsim.Renderer(W, H)
    assert len(pngs) == 13
    for png in pngs:
        frame = renderer.render(world, panel=True)  # the program's frames show the panel
        assert frame.shape == (H, W, 4) and frame.dtype == np.uint8
        expected = np.round(mpimg.imread(png) * 255).astype(np.uint8)  # RGB, 8 bits
        np.testing.assert_array_equal(frame[..., :3], expected)
        assert (frame[..., 3] == 255).all()
        world.step(steps_per_frame)


def project(point, eye, target, fov_deg, width, height):
    """Pixel (column, row from the top) of a world point under a look-at camera with y up."""
    forward = np.subtract(target, eye) / np.linalg.norm(np.subtract(target, eye))
    right = np.cross(forward, [0, 1, 0])
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    d = np.subtract(point, eye)
    depth = d @ forward
    f = 1 / np.tan(np.radians(fov_deg) / 2)
    x_ndc = f * (d @ right) / depth / (width / height)
    y_ndc = f * (d @ up) / depth
    return int((x_ndc + 1) / 2 * width), int((1 - y_ndc) / 2 * height)


def test_a_red_ball_is_drawn_where_the_camera_sees_it():
    world = rbsim.World(dt=1 / 60)
    world.add_plane()
    ball = world.add_body(shape={"type": "sphere", "radius": 0.3}, mass=1, position=[0.8, 1.5, -0.5], color=[1, 0, 0])
    world.step(20)  # falling: the picture follows the state
    camera = {"eye": [0, 1.5, 5], "target": [0, 1, 0], "fov_deg": 40}
    frame = rbsim.Renderer(W, H).render(world, camera=camera, overlay=False, axes=False)
    col, row = project(world.x[world.index_of(ball)], camera["eye"], camera["target"], 40, W, H)
    r, g, b = frame[row, col, :3].astype(int)
    assert r > 100 and r > 2 * g and r > 2 * b, (r, g, b)
    col0, row0 = project([-0.8, 1.5, -0.5], camera["eye"], camera["target"], 40, W, H)  # where no ball is
    r0, g0, b0 = frame[row0, col0, :3].astype(int)
    assert not (r0 > 2 * g0 and r0 > 2 * b0)


def test_video_writer_writes_every_frame(tmp_path):
    world = rbsim.World(dt=1 / 60)
    world.add_plane()
    world.add_body(shape={"type": "box", "extents": [0.5, 0.5, 0.5]}, mass=1, position=[0, 2, 0])
    renderer = rbsim.Renderer(W, H)
    path = tmp_path / "clips" / "drop.mp4"
    with rbsim.VideoWriter(str(path), W, H, fps=30) as video:
        for _ in range(15):
            video.write(renderer.render(world))
            world.step(2)
    assert video.frames == 15
    probe = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                            "stream=nb_read_frames,width,height", "-of", "json", str(path)],
                           capture_output=True, text=True, check=True)
    stream = json.loads(probe.stdout)["streams"][0]
    assert (int(stream["nb_read_frames"]), stream["width"], stream["height"]) == (15, W, H)


@pytest.mark.parametrize("keywords,field", [({"width": 15}, "width"), ({"height": 181}, "height"),
                                            ({"width": 10000}, "width"), ({"gl": "vulkan"}, "gl"),
                                            ({"samples": 0}, "samples")])
def test_bad_renderer_arguments(keywords, field):
    with pytest.raises(rbsim.InputError) as e:
        rbsim.Renderer(**keywords)
    assert e.value.field == field


def test_bad_view_and_frames(tmp_path):
    world = rbsim.World()
    renderer = rbsim.Renderer(W, H)
    with pytest.raises(rbsim.InputError) as e:
        renderer.render(world, camera={"eye": [0, 1, 0], "target": [0, 1, 0]})
    assert e.value.field == "camera.target"
    with pytest.raises(rbsim.InputError) as e:
        renderer.render(world, size=[640, 360])
    assert e.value.field == "size"
    video = rbsim.VideoWriter(str(tmp_path / "a.mp4"), W, H)
    with pytest.raises(rbsim.InputError) as e:
        video.write(np.zeros((H, W, 3), np.uint8))
    assert e.value.field == "frame"
    video.close()
    with pytest.raises(rbsim.RenderError):
        video.write(np.zeros((H, W, 4), np.uint8))
    (tmp_path / "file").write_text("")
    with pytest.raises(rbsim.RenderError):
        rbsim.VideoWriter(str(tmp_path / "file" / "b.mp4"), W, H)


# The renderer's camera planes [m] (render::Camera) and its 24-bit depth buffer.
NEAR, FAR = 0.05, 200.0
DEPTH_STEP = 1 / (2 ** 24 - 1)
# A surface's depth is within 2 steps: one for rounding to 24 bits, one for the float32 depth the
# vertex shader computes, whose ulp near 1 is a step as well (measured: 0.25 to 1.5 steps, eye 0.5 to 50 m).
SURFACE_STEPS = 2
# The colour pass pushes bodies back by glPolygonOffset(1, 1) so their outlines win the depth test:
# on llvmpipe 3 steps of the buffer (tests/render/extra_images_test.cpp measures it).
BODY_OFFSET_STEPS = 3
FOV = 45.0  # the view's default vertical field of view [deg]


def depth_resolution(z, steps=SURFACE_STEPS):
    """`steps` steps of the depth buffer at distance z [m] (dz/dd = z^2 (f - n) / (f n)), and float32's half ulp."""
    return steps * z * z * (FAR - NEAR) / (FAR * NEAR) * DEPTH_STEP + 0.5 * z * 2.0 ** -23


def focal_pixels(height):
    return height / 2 / np.tan(np.radians(FOV) / 2)


def static_world(grid_plane=True):
    world = rbsim.World(gravity=[0, 0, 0])
    if grid_plane:
        world.add_plane()
    return world


def test_the_panel_is_off_unless_asked_for():
    world = static_world()
    world.add_body(shape={"type": "box", "extents": [0.5, 0.5, 0.5]}, mass=1, position=[0, 0.5, 0])
    renderer = rbsim.Renderer(W, H)
    plain = renderer.render(world)
    np.testing.assert_array_equal(plain, renderer.render(world, overlay=False))
    with_panel = renderer.render(world, panel=True)
    # The panel takes a column on the left and the scene moves right of it.
    assert (with_panel[:, : W // 4] != plain[:, : W // 4]).any(axis=-1).mean() > 0.5
    with pytest.raises(rbsim.InputError) as e:
        renderer.render(world, panel=True, overlay=False)
    assert e.value.field == "panel"
    for keyword in ("depth", "segmentation", "panel"):
        with pytest.raises(rbsim.InputError) as e:
            renderer.render(world, **{keyword: 1})
        assert e.value.field == keyword


def test_images_asked_for_come_in_a_dict_with_the_same_colour_image():
    world = static_world()
    ball = world.add_body(shape={"type": "sphere", "radius": 0.4}, mass=1, position=[0, 0.4, 0])
    renderer = rbsim.Renderer(W, H)
    plain = renderer.render(world)
    assert isinstance(plain, np.ndarray)
    only_depth = renderer.render(world, depth=True)
    assert set(only_depth) == {"rgba", "depth"}
    both = renderer.render(world, depth=True, segmentation=True)
    assert set(both) == {"rgba", "depth", "segmentation", "bodies"}
    np.testing.assert_array_equal(both["rgba"], plain)
    np.testing.assert_array_equal(both["depth"], only_depth["depth"])
    assert both["depth"].shape == (H, W) and both["depth"].dtype == np.float32
    assert both["segmentation"].shape == (H, W) and both["segmentation"].dtype == np.int32
    assert both["bodies"] == [ball]


def test_depth_of_a_plane_seen_head_on_is_its_distance():
    world = static_world()
    height = 4.0
    out = rbsim.Renderer(W, H).render(world, depth=True, segmentation=True, axes=False,
                                      camera={"eye": [0.3, height, 0.2], "target": [0.3, 0, 0.2], "up": [0, 0, -1]})
    assert np.abs(out["depth"] - height).max() <= depth_resolution(height)
    assert (out["segmentation"] == -2).all()  # the ground, every pixel


def test_depth_of_a_sphere_s_nearest_point_is_distance_minus_radius():
    world = static_world()
    radius, centre, eye_height = 0.5, np.array([0.0, 1.0, 0.0]), 5.0
    ball = world.add_body(shape={"type": "sphere", "radius": radius}, mass=1, static=True, position=centre)
    # The drawn sphere is a 48 x 24 polyhedron inscribed in it, with a vertex at its pole (0, r, 0):
    # under the camera looking straight down, its nearest point is the sphere's.
    assert np.isclose(world.body_vertices(ball), [0, radius, 0], atol=1e-12).all(axis=1).any()
    renderer = rbsim.Renderer(W, H)
    out = renderer.render(world, depth=True, segmentation=True, axes=False,
                          camera={"eye": [0, eye_height, 0], "target": [0, 0, 0], "up": [0, 0, -1]})
    depth = out["depth"]
    nearest = eye_height - centre[1] - radius
    row, col = np.unravel_index(np.argmin(depth), depth.shape)
    assert abs(row + 0.5 - H / 2) <= 1 and abs(col + 0.5 - W / 2) <= 1, (row, col)
    # Pixel centres stand half a pixel (diagonally) from the axis, where the pole's fan of triangles
    # rises at pi/48 from the tangent plane; the polygon offset adds that slope once more per pixel.
    pixel = nearest / focal_pixels(H)
    slope = np.tan(np.pi / 48)
    tolerance = depth_resolution(nearest, SURFACE_STEPS + BODY_OFFSET_STEPS) + (np.sqrt(0.5) + 1) * pixel * slope
    assert abs(depth.min() - nearest) <= tolerance, (depth.min() - nearest, tolerance)
    assert out["segmentation"][row, col] == 0
    # Where the sphere is not, the ground 5 m down: depth and segmentation see the same surfaces.
    ground = out["segmentation"] == -2
    assert np.abs(depth[ground] - eye_height).max() <= depth_resolution(eye_height)
    assert set(np.unique(out["segmentation"])) == {-2, 0}


def pixel_of(point, eye, target, up=(0, 1, 0)):
    """Continuous pixel coordinates (column, row from the top; pixel i spans [i, i + 1))."""
    forward = np.subtract(target, eye) / np.linalg.norm(np.subtract(target, eye))
    right = np.cross(forward, up)
    right /= np.linalg.norm(right)
    true_up = np.cross(right, forward)
    d = np.subtract(point, eye)
    f = focal_pixels(H)
    return W / 2 + f * (d @ right) / (d @ forward), H / 2 - f * (d @ true_up) / (d @ forward)


def test_segmentation_of_a_box_seen_face_on_covers_its_projected_face():
    world = static_world(grid_plane=False)
    centre = np.array([0.2, 1.1, 0.0])
    box = world.add_body(shape={"type": "box", "extents": [1.0, 0.6, 0.8]}, mass=1, static=True, position=centre)
    half = world.body_vertices(box).max(axis=0)
    eye, target = [0, 1, 6], [0, 1, 0]
    out = rbsim.Renderer(W, H).render(world, depth=True, segmentation=True, grid=False, axes=False,
                                      camera={"eye": eye, "target": target})
    seg, depth = out["segmentation"], out["depth"]
    left, top = pixel_of(centre + [-half[0], half[1], half[2]], eye, target)
    right, bottom = pixel_of(centre + [half[0], -half[1], half[2]], eye, target)
    columns = np.ceil(right - 0.5) - np.floor(left - 0.5) - 1  # pixel centres inside: GL's rule
    rows = np.ceil(bottom - 0.5) - np.floor(top - 0.5) - 1
    count = (seg == 0).sum()
    assert count == columns * rows
    width, height = right - left, bottom - top
    assert abs(count - width * height) <= width + height + 1  # the area, up to the edge pixels
    face = eye[2] - (centre[2] + half[2])
    assert np.abs(depth[seg == 0] - face).max() <= depth_resolution(face, SURFACE_STEPS + BODY_OFFSET_STEPS)
    # No ground (grid=False): everything else is sky, depth +inf.
    assert set(np.unique(seg)) == {-1, 0}
    assert np.isinf(depth[seg == -1]).all() and np.isfinite(depth[seg == 0]).all()


def test_every_body_in_the_image_is_a_body_in_view_and_every_body_in_view_is_in_it():
    world = static_world()
    eye, target = np.array([0.0, 2.0, 8.0]), np.array([0.0, 1.0, 0.0])
    places = [[-2.5, 0.3, 0], [-1, 0.3, 1], [0.5, 0.3, -1], [2, 0.3, 0.5], [0, 2.2, 0],  # in view
              [0, 1, 12], [-30, 0.3, 0], [25, 0.3, -3], [0, 30, 0]]  # behind the eye, far left, far right, far above
    ids = [world.add_body(shape={"type": "box", "extents": [0.5, 0.5, 0.5]}, mass=1, static=True, position=p)
           for p in places]
    world.remove_body(ids[1])  # the last body moves into its row
    renderer = rbsim.Renderer(W, H)
    out = renderer.render(world, depth=True, segmentation=True, camera={"eye": list(eye), "target": list(target)})
    assert out["bodies"] == [world.id_at(k) for k in range(len(world))]

    def in_view(row):
        corners = world.vertices(world.id_at(row))
        if ((corners - eye) @ (target - eye) <= 0).any():
            return False
        pixels = np.array([pixel_of(c, eye, target) for c in corners])
        inside = (pixels[:, 0] > 0) & (pixels[:, 0] < W) & (pixels[:, 1] > 0) & (pixels[:, 1] < H)
        assert inside.all() or not inside.any(), row  # the scene has no body half in view
        return inside.all()

    seen = {int(v) for v in np.unique(out["segmentation"]) if v >= 0}
    assert seen == {row for row in range(len(world)) if in_view(row)}
    assert len(seen) == 4  # the one removed was in view
    assert {int(v) for v in np.unique(out["segmentation"]) if v < 0} == {-1, -2}
    sky = out["segmentation"] == -1
    assert sky[0].all() and np.isinf(out["depth"][sky]).all() and np.isfinite(out["depth"][~sky]).all()


def test_the_docs_camera_images_example_runs():
    """docs/python.md's "Camera images" snippet, as written (it asserts the body it finds)."""
    text = (SOURCE / "docs" / "python.md").read_text()
    code = text.split("## Camera images", 1)[1].split("```python\n", 1)[1].split("```", 1)[0]
    exec(compile(code, "docs/python.md", "exec"), {})


def test_with_the_panel_the_images_cover_the_scene_s_pane_only():
    world = static_world()
    ball = world.add_body(shape={"type": "sphere", "radius": 0.5}, mass=1, static=True, position=[0, 0.5, 0])
    renderer = rbsim.Renderer(W, H)
    plain = renderer.render(world, depth=True, segmentation=True)
    out = renderer.render(world, depth=True, segmentation=True, panel=True)
    np.testing.assert_array_equal(out["rgba"], renderer.render(world, panel=True))
    seg, depth = out["segmentation"], out["depth"]
    # The panel's column on the left shows no surface; the scene, narrower, still shows the ball.
    column = (seg == -1).all(axis=0).argmin()  # the first column with a surface
    assert column > W // 5 and (seg[:, :column] == -1).all() and np.isinf(depth[:, :column]).all()
    assert 0 < (seg == 0).sum() < (plain["segmentation"] == 0).sum()
    assert np.isfinite(depth[seg != -1]).all() and out["bodies"] == [ball]
