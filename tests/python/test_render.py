"""Frames from Python are the program's frames; clips are written by the program's writer."""
import glob
import json
import subprocess

import matplotlib.image as mpimg
import numpy as np
import pytest
import rbsim

from conftest import SCENES, run_cli

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
        frame = renderer.render(world)
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
