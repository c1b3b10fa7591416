"""A graph writes what its job file writes, byte for byte, and is that
job file (to_toml / from_toml)."""

import os

import exrcomp

from conftest import exrcomp as command


def comp_graph(plates, out):
    g = exrcomp.Graph()
    fg = g.read(str(plates / "fg.####.exr"))
    bg = g.read(str(plates / "bg.####.exr"), name="bg")
    comp = g.over(fg, bg)
    soft = g.blur(comp, radius=2, filter="box")
    g.write(g.grade(soft, gain=(1.1, 1.0, 0.9)), str(out), compression="zip",
            attrib=["shot=010:string"])
    return g


def test_a_graph_writes_its_job_files_bytes(plates, tmp_path):
    g = comp_graph(plates, tmp_path / "py" / "c.####.exr")
    result = g.run(frames="1-4")
    assert result == {"written": [1, 2, 3, 4]}
    job = tmp_path / "job.toml"
    job.write_text(g.to_toml())
    command("run", job, "-o", tmp_path / "cli" / "c.####.exr", "--frames", "1-4", "-q")
    for frame in range(1, 5):
        ours = (tmp_path / "py" / f"c.{frame:04}.exr").read_bytes()
        theirs = (tmp_path / "cli" / f"c.{frame:04}.exr").read_bytes()
        assert ours == theirs, f"frame {frame} differs"


def test_to_toml_and_from_toml_round_trip(plates, tmp_path):
    g = comp_graph(plates, tmp_path / "c.####.exr")
    g.frames = "1-2"
    text = g.to_toml()
    again = exrcomp.Graph.from_toml(text)
    assert again.to_toml() == text
    assert again.frames == "1-2"
    assert 'op = "over"' in text and 'inputs = ["blur1"]' in text


def test_a_job_file_read_back_runs(plates, tmp_path):
    text = comp_graph(plates, tmp_path / "c.####.exr").to_toml()
    assert exrcomp.Graph.from_toml(text).run(frames="2") == {"written": [2]}
    assert (tmp_path / "c.0002.exr").exists()


def test_plan_checks_without_writing(plates, tmp_path):
    g = comp_graph(plates, tmp_path / "c.####.exr")
    plan = g.plan(frames="1-3")
    assert plan["memory"] > 0
    assert [os.path.basename(p) for p in plan["writes"]] == ["c.0001.exr", "c.0002.exr",
                                                             "c.0003.exr"]
    assert len(plan["reads"]) == 6
    assert list(tmp_path.iterdir()) == []


def test_info_is_info_json(plates):
    import json
    path = plates / "bg.0001.exr"
    assert exrcomp.info(path) == json.loads(command("info", "--json", path).stdout)
