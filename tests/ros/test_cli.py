"""``seal localize --bag`` / ``--goals`` and ``seal import-bag`` on bags the tests write: the beliefs follow
the bag's detections, the goals read back as PoseStamped, and bad input exits 1 with one message and no file."""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

import pytest
import yaml
from typer.testing import CliRunner

pytest.importorskip("rosbags")

from seal_cli.cli import app  # noqa: E402
from seal_cli.sensing.observations import read_observations  # noqa: E402
from tests.ros.bagfiles import write_run  # noqa: E402

runner = CliRunner()
PATH = [(-6.0, -3.0), (-1.0, -2.5), (2.5, -4.7), (5.0, -4.5), (7.0, -3.0)]
"""From the living room into the kitchen, where the spoon lies on the counter at (8.3, -4.1)."""


def poses(n: int = 50) -> list[tuple[float, float, float, float]]:
    out = []
    for i in range(n):
        f = i / (n - 1) * (len(PATH) - 1)
        k = min(int(f), len(PATH) - 2)
        (x0, y0), (x1, y1) = PATH[k], PATH[k + 1]
        u = f - k
        out.append((100.0 + i * 0.2, x0 + u * (x1 - x0), y0 + u * (y1 - y0), 0.0))
    return out


def kitchen_run(path: Path) -> Path:
    """Detections every second; the spoon seen (in base_link) once the robot is within 5 m of it (in a ROS 1
    bag, as class id 44, COCO's spoon)."""
    track = poses()
    looks = []
    for t, x, y, _ in track[::5]:
        near = (8.3 - x) ** 2 + (-4.1 - y) ** 2 < 4.5 ** 2
        spoon = 44 if path.suffix == ".bag" else "spoon"
        looks.append((t + 0.1, "base_link", [(spoon, 8.3 - x, -4.1 - y, 0.9)] if near else []))
    return write_run(path, track, looks, pose_source="tf")


def invoke(*args: str) -> Any:
    return runner.invoke(app, list(args))


def localize(*args: str) -> dict[str, Any]:
    result = invoke("localize", "--map", "apartment", "--task", "stir the cup", "--steps", "0", *args, "--json")
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


@pytest.mark.parametrize("name", ["run.mcap", "run.bag"])
def test_localize_from_a_bag_believes_what_it_saw(tmp_path: Path, name: str) -> None:
    labels = tmp_path / "labels.yaml"
    labels.write_text("{44: spoon, 47: cup}\n")
    data = localize("--bag", str(kitchen_run(tmp_path / name)), "--labels", str(labels))
    assert data["updates"] == 10
    spoon = next(o for o in data["objects"] if o["class"] == "spoon")
    assert spoon["rooms"]["kitchen"] > 0.95  # seen on the counter; the bedroom's prior is gone
    assert abs(spoon["best"][0] - 8.3) < 0.5 and abs(spoon["best"][1] + 4.1) < 0.5


def test_import_bag_gives_the_same_beliefs_as_the_bag(tmp_path: Path) -> None:
    bag = kitchen_run(tmp_path / "run.mcap")
    out = tmp_path / "observations.yaml"
    result = invoke("import-bag", str(bag), "-o", str(out))
    assert result.exit_code == 0, result.output
    observations = read_observations(out)
    assert len(observations) == 10 and observations[-1].detections[0][0] == "spoon"
    assert localize("--observations", str(out)) == localize("--bag", str(bag))


@pytest.mark.parametrize("name", ["r\nx: [.mcap", "r\u2028x\x85y.mcap", "r\udcffz.mcap"])
def test_import_bag_of_any_name_writes_a_file_that_reads_back(tmp_path: Path, name: str) -> None:
    # the bag's name went into the file's first comment as it was: a newline made the rest of it a line of YAML
    # (the file written could not be read back); a byte that is not UTF-8 was a UnicodeEncodeError (hostile16)
    bag = kitchen_run(tmp_path / "run.mcap").rename(tmp_path / name)
    out = tmp_path / "observations.yaml"
    result = invoke("import-bag", str(bag), "-o", str(out))
    assert result.exit_code == 0, result.output
    assert len(read_observations(out)) == 10
    assert out.read_text(encoding="utf-8").splitlines()[1] == "observations:"  # the comment is one line


@pytest.mark.parametrize("name", ["goals.yaml", "goals.mcap", "goals.bag", "goals_db3"])
def test_goals_read_back_as_pose_stamped(tmp_path: Path, name: str) -> None:
    bag = kitchen_run(tmp_path / "run.mcap")
    target = tmp_path / name
    data = localize("--bag", str(bag), "--goals", str(target))
    best = {f["frame"]: f["best"] for f in data["frames"]}
    if name.endswith(".yaml"):
        document = yaml.safe_load(target.read_text())
        assert document["frame_id"] == "map"
        goals = [(g["frame"], g["pose"]) for g in document["goals"]]
        assert [g for g, _ in goals] == ["pick_spoon", "stir_cup_spoon"]
        assert [v for _, p in goals for v in p[:2]] == pytest.approx([*best["Pick"], *best["Stir"]], abs=1e-3)
        return
    from rosbags.highlevel import AnyReader

    from seal_cli.ros.messages import typestore
    from seal_cli.ros.transforms import quaternion_yaw

    with AnyReader([target], default_typestore=typestore(name.endswith(".bag"))) as reader:
        assert [(c.topic, c.msgtype) for c in reader.connections] == [("/goal_pose", "geometry_msgs/msg/PoseStamped")]
        messages = [reader.deserialize(raw, c.msgtype) for c, _, raw in reader.messages()]
    assert [m.header.frame_id for m in messages] == ["map", "map"]
    assert [v for m in messages for v in (m.pose.position.x, m.pose.position.y)] == pytest.approx(
        [*best["Pick"], *best["Stir"]], abs=1e-3)
    q = messages[0].pose.orientation
    yaw = float(quaternion_yaw([[q.x, q.y, q.z, q.w]])[0])
    assert -3.2 < yaw < 3.2 and abs(q.x) + abs(q.y) < 1e-9  # a turn about z only


# -- bad input: one message, exit 1, no file --------------------------------------------------------
def refused(*args: str, out: Path | None = None) -> str:
    result = invoke(*args)
    assert result.exit_code == 1, result.output
    assert "Traceback" not in result.output
    lines = [line for line in result.stderr.splitlines() if line.startswith("error:")]
    assert len(lines) == 1, result.stderr
    if out is not None:
        assert not out.exists() and not [p for p in out.parent.iterdir() if p.name.startswith(f".{out.name}")]
    return lines[0]


def test_bad_bags_are_refused(tmp_path: Path) -> None:
    (tmp_path / "notes.mcap").write_text("hello\n")
    out = tmp_path / "obs.yaml"
    assert "cannot read this as a ROS bag" in refused("import-bag", str(tmp_path / "notes.mcap"), "-o", str(out),
                                                      out=out)
    bag = kitchen_run(tmp_path / "run.mcap")
    assert "no topic /dets in the bag" in refused("import-bag", str(bag), "-o", str(out), "--detections-topic",
                                                  "/dets", out=out)
    assert "'world'" in refused("import-bag", str(bag), "-o", str(out), "--frame", "world", out=out)
    assert "is the bag itself" in refused("import-bag", str(bag), "-o", str(bag))
    assert bag.is_file()


def test_bad_labels_are_refused_at_their_line(tmp_path: Path) -> None:
    bag = kitchen_run(tmp_path / "run.bag")
    labels = tmp_path / "labels.yaml"
    labels.write_text("44: spoon\n47: [cup, mug]\n")
    assert refused("import-bag", str(bag), "-o", str(tmp_path / "o.yaml"), "--labels", str(labels)) == \
        f"error: {labels}:2:5: the label of 47 must be a single value, not a list"


def test_localize_refuses_conflicting_and_dangling_options(tmp_path: Path) -> None:
    bag = kitchen_run(tmp_path / "run.mcap")
    assert "not both --observations and --bag" in refused("localize", "--map", "apartment", "--bag", str(bag),
                                                     "--observations", str(bag))
    assert "give --bag too" in refused("localize", "--map", "apartment", "--pose-topic", "/odom")
    goals = tmp_path / "goals.yaml"
    assert "give --task" in refused("localize", "--map", "apartment", "--bag", str(bag), "--goals", str(goals),
                                    out=goals)
    rrd = tmp_path / "out.rrd"
    message = refused("localize", "--map", "apartment", "--task", "stir the cup", "--bag", str(bag),
                      "--detections-topic", "/nope", "--rrd", str(rrd), out=rrd)
    assert "no topic /nope" in message
    assert "folder" in refused("localize", "--map", "apartment", "--task", "stir the cup", "--bag", str(bag),
                               "--goals", str(tmp_path / "missing" / "goals.yaml"))
    before = bag.read_bytes()
    assert "is an input or another output of the run" in refused("localize", "--map", "apartment", "--task",
                                                                 "stir the cup", "--bag", str(bag), "--goals", str(bag))
    assert bag.read_bytes() == before


def test_without_rosbags_the_way_out_is_named(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    import sys

    monkeypatch.setitem(sys.modules, "rosbags", None)  # import rosbags now raises ImportError
    message = refused("import-bag", str(tmp_path / "run.mcap"), "-o", str(tmp_path / "o.yaml"))
    assert "pip install 'seal[ros]'" in message


def test_validate_reads_the_occupancy_from_the_bag(tmp_path: Path) -> None:
    from tests.ros.test_occupancy_bag import apartment_with, saved_as_message

    saved_as_message(tmp_path)
    good = apartment_with(tmp_path, "occupancy: mapping.mcap")
    assert invoke("validate", str(good)).exit_code == 0
    bad = apartment_with(tmp_path, "occupancy: {bag: mapping.mcap, topic: /nope}")
    result = invoke("validate", str(bad))
    assert result.exit_code == 1 and "no topic /nope in the bag" in result.output


def test_bench_ros_reads_and_filters_every_message() -> None:
    result = invoke("bench", "ros", "--format", "mcap", "--format", "ros1", "--poses", "60", "--messages", "12",
                    "--json")
    assert result.exit_code == 0, result.output
    runs = json.loads(result.stdout)["runs"]
    assert [r["format"] for r in runs] == ["mcap", "ros1"]
    for r in runs:
        assert (r["poses"], r["messages"], r["updates"], r["frames"], r["objects"]) == (60, 12, 12, 3, 2)
        assert r["detections"] > 0 and r["updates_per_s"] > 0  # the loop passes the spoon and the cup
        assert r["recorded_updates_per_s"] > 0 and 10_000 < r["rrd_bytes"] < r["bag_bytes"] * 10  # a recording
    assert runs[0]["detections"] == runs[1]["detections"]  # ROS 1's integer ids name the same classes
    assert "unknown format" in refused("bench", "ros", "--format", "ros3")


def test_import_bag_and_goals_beside_a_link_loop_end_with_a_message(tmp_path: Path,
                                                                    monkeypatch: pytest.MonkeyPatch) -> None:
    # Path.resolve raises RuntimeError on a link loop: both were tracebacks (hostile17)
    monkeypatch.chdir(tmp_path)
    Path("loop").symlink_to("loop")
    result = runner.invoke(app, ["import-bag", "loop", "-o", "o.yaml"])
    assert result.exit_code == 1 and "loop: cannot read this bag: Too many levels of symbolic links" in result.output
    result = runner.invoke(app, ["localize", "--map", "apartment", "--task", "find the cup", "--steps", "1",
                                 "--particles", "20", "--goals", "g.yaml", "--rrd", "loop"])
    assert result.exit_code == 1 and "cannot write --rrd loop" in result.output
    assert not Path("o.yaml").exists() and not Path("g.yaml").exists()


@pytest.mark.parametrize("name", ["goals.txt", "goals.json", "goals.png"])
def test_goals_with_a_suffix_of_no_format_are_refused(tmp_path: Path, name: str) -> None:
    """hostile19: `--goals goals.txt` wrote a ROS 2 bag folder called goals.txt."""
    target = tmp_path / name
    message = refused("localize", "--map", "apartment", "--task", "stir the cup", "--steps", "1", "--particles", "10",
                      "--goals", str(target), out=target)
    assert f"seal writes goals as YAML (.yaml, .yml), a ROS 1 bag (.bag), an MCAP bag (.mcap) or a ROS 2 bag folder " \
           f"(a name without a suffix), not {target.suffix}" in message


def test_a_map_whose_origin_turns_its_image_is_warned_of_with_a_bag(tmp_path: Path) -> None:
    """robot5: map_server's origin may carry a yaw; seal turns the image (as RViz draws it), but amcl and Nav2's
    costmaps ignore it, so the poses of a robot localised by them are in the frame of the unturned image."""
    from seal_cli.resources import map_path

    apartment = Path(map_path("apartment"))
    text = apartment.read_text().replace("image: apartment.pgm", f"image: {apartment.parent / 'apartment.pgm'}")
    assert "origin: [-10.0, -7.0, 0.0]" in text
    (tmp_path / "turned.yaml").write_text(text.replace("origin: [-10.0, -7.0, 0.0]", "origin: [-10.0, -7.0, 0.01]"))
    (tmp_path / "flat.yaml").write_text(text)
    bag = kitchen_run(tmp_path / "run.mcap")
    for name, warned in (("turned", True), ("flat", False)):
        result = invoke("localize", "--map", str(tmp_path / f"{name}.yaml"), "--task", "stir the cup", "--steps", "0",
                        "--bag", str(bag))
        assert result.exit_code == 0, result.output
        said = "origin turns its image by 0.01 rad (0.6°)" in result.stderr and "amcl and Nav2's costmaps ignore" \
            in result.stderr
        assert said is warned, result.stderr


def test_goals_where_a_bag_folder_goes_are_refused_before_the_run(tmp_path: Path) -> None:
    """hostile27: a name without a suffix is a ROS 2 bag's folder; `--goals out` onto a file, or `--goals /dev/full`,
    ran the whole filter and then said "Not a directory". Both are refused first, naming --goals; the file is kept."""
    target = tmp_path / "out"
    target.write_text("a file\n")
    message = refused("localize", "--map", "apartment", "--task", "stir the cup", "--steps", "1", "--particles", "10",
                      "--goals", str(target))
    assert f"cannot write --goals {target}: a name without a suffix is written as a ROS 2 bag's folder" in message
    assert target.read_text() == "a file\n"
    assert "--goals /dev/full" in refused("localize", "--map", "apartment", "--task", "stir the cup", "--steps", "1",
                                          "--goals", "/dev/full")


def test_goals_as_a_bag_hard_linked_to_an_input_are_refused(tmp_path: Path) -> None:
    """hostile27: `--goals g.bag`, g.bag a hard link to the observations, was replaced by the bag (the path differs,
    the file is the same)."""
    bag = kitchen_run(tmp_path / "run.mcap")
    link = tmp_path / "g.mcap"
    link.hardlink_to(bag)
    before = bag.read_bytes()
    message = refused("localize", "--map", "apartment", "--task", "stir the cup", "--bag", str(bag), "--goals",
                      str(link))
    assert f"--goals {link} is an input or another output of the run ({bag})" in message
    assert bag.read_bytes() == before and link.read_bytes() == before


def test_a_killed_goal_writer_s_work_folder_is_swept_and_the_bag_reads_back(tmp_path: Path) -> None:
    """hostile27: the bag writer's work folder was ``tempfile.mkdtemp``'s ``.g.mcap.2x8f_k1``, left for ever by a
    killed run; it now carries the writer's process id (``fileio.work_folder``), and the next write sweeps it."""
    stale = tmp_path / ".g.mcap.seal999999-0123abcd.tmp"
    (stale / "out").mkdir(parents=True)
    (stale / "out" / "half.mcap").write_bytes(b"half")
    result = invoke("localize", "--map", "apartment", "--task", "stir the cup", "--steps", "1", "--particles", "10",
                    "--goals", str(tmp_path / "g.mcap"))
    assert result.exit_code == 0, result.output
    assert sorted(p.name for p in tmp_path.iterdir()) == ["g.mcap"]
    from rosbags.highlevel import AnyReader

    from seal_cli.ros.messages import typestore

    with AnyReader([tmp_path / "g.mcap"], default_typestore=typestore(False)) as reader:
        assert [c.topic for c in reader.connections] == ["/goal_pose"] and len(list(reader.messages())) == 2


def test_a_bag_folders_own_files_are_never_outputs(tmp_path: Path) -> None:
    """``import-bag x -o x/metadata.yaml`` and ``localize --bag x --goals x/metadata.yaml`` replaced the bag's
    metadata, and ``-o h.yaml``, a hard link to its database, the database (hostile29): rosbags reads them, not seal,
    so nothing guarded them. Now an input folder's files are inputs; a new file in the folder is still written."""
    bag = kitchen_run(tmp_path / "run_db3")
    before = {p.name: p.read_bytes() for p in bag.iterdir()}
    (tmp_path / "h.yaml").hardlink_to(next(p for p in bag.iterdir() if p.suffix == ".db3"))
    for args in (("import-bag", str(bag), "-o", str(bag / "metadata.yaml")),
                 ("import-bag", str(bag), "-o", str(tmp_path / "h.yaml")),
                 ("localize", "--map", "apartment", "--bag", str(bag), "--task", "stir the cup", "--steps", "0",
                  "--goals", str(bag / "metadata.yaml"))):
        assert "would overwrite the input" in refused(*args)
    assert {p.name: p.read_bytes() for p in bag.iterdir()} == before
    result = invoke("import-bag", str(bag), "-o", str(bag / "obs.yaml"))
    assert result.exit_code == 0, result.output
    assert read_observations(bag / "obs.yaml")


@pytest.mark.parametrize(("old", "new", "says"), [
    (b"ros_distro: rosbags", b'ros_distro: !!python/object/apply:os.system ["true"]', "the tag !!python"),
    (b"    message_count: ", b"    message_count: " + b"9" * 5000 + b"\n    its_count: ",
     "cannot read this value: an integer of 5,000"),
    (b"rosbag2_bagfile_information:", b"rosbag2_bagfile_information: [", "YAML syntax error"),
    (b"\n", b"\n# caf\xe9\n", "this file is not UTF-8"),
])
def test_a_bag_folders_metadata_edited_by_hand_is_refused_at_its_line(tmp_path: Path, old: bytes, new: bytes,
                                                                       says: str) -> None:
    """rosbags' own failures named the folder alone, with its YAML's message or a Python limit's (hostile29)."""
    bag = kitchen_run(tmp_path / "run_db3")
    meta = bag / "metadata.yaml"
    meta.write_bytes(meta.read_bytes().replace(old, new, 1))
    said = refused("import-bag", str(bag), "-o", str(tmp_path / "o.yaml"), out=tmp_path / "o.yaml")
    assert re.match(rf"error: {re.escape(str(meta))}:\d+:\d+: {says}", said), said


def test_a_bag_that_is_a_fifo_or_holds_one_is_refused_by_its_kind(tmp_path: Path) -> None:
    """hostile30: rosbags opened a FIFO named .mcap (or a ROS 2 bag's database that is one) and waited for ever."""
    import os

    os.mkfifo(tmp_path / "f.mcap")
    out = tmp_path / "obs.yaml"
    said = refused("import-bag", str(tmp_path / "f.mcap"), "-o", str(out), out=out)
    assert "f.mcap: cannot read this bag: it is a FIFO (named pipe)" in said
    (tmp_path / "x").mkdir()
    (tmp_path / "x" / "metadata.yaml").write_text("rosbag2_bagfile_information:\n  version: 5\n")
    os.mkfifo(tmp_path / "x" / "out.db3")
    said = refused("import-bag", str(tmp_path / "x"), "-o", str(out), out=out)
    assert "out.db3: cannot read this bag file: it is a FIFO (named pipe)" in said


def test_a_goal_bag_that_fails_to_be_written_names_the_option(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """hostile30: past ``ulimit -f`` it was "cannot write .g.mcap.seal…tmp.mcap: File too large", the temporary."""
    import errno

    from seal_cli.ros import writing

    def full(*_: object, **__: object) -> None:
        raise OSError(errno.EFBIG, "File too large")

    monkeypatch.setattr(writing, "_write", full)
    result = invoke("localize", "--map", "apartment", "--task", "go to the kitchen", "--steps", "0", "--goals",
                    str(tmp_path / "g.mcap"))
    assert result.exit_code == 1 and "cannot write --goals" in result.output and "File too large" in result.output
    assert list(tmp_path.iterdir()) == []
