"""Errors are exceptions of the command line's kinds and text, with the
file and frame they name."""

import pytest

import exrcomp

from conftest import exrcomp as command


def over(plates, bg, out):
    g = exrcomp.Graph()
    g.write(g.over(g.read(str(plates / "fg.####.exr")), g.read(str(bg))), str(out))
    return g


def test_a_damaged_frame_is_an_input_error_naming_file_and_frame(plates, tmp_path):
    for frame in (1, 2, 3):
        data = (plates / f"bg.{frame:04}.exr").read_bytes()
        if frame == 2:
            data = data[: len(data) // 2]
        (tmp_path / f"bg.{frame:04}.exr").write_bytes(data)
    g = over(plates, tmp_path / "bg.####.exr", tmp_path / "out" / "c.####.exr")
    with pytest.raises(exrcomp.InputError) as raised:
        g.run(frames="1-3")
    job = tmp_path / "job.toml"
    job.write_text(g.to_toml())
    cli = command("run", job, "--frames", "1-3", "-q", "-o", tmp_path / "o2" / "c.####.exr",
                  check=False)
    assert cli.returncode == raised.value.exit_code == 3
    assert cli.stderr.strip().splitlines()[-1] == f"exrcomp: error: {raised.value}"
    assert raised.value.file == str(tmp_path / "bg.0002.exr")
    assert raised.value.frame == 2


def test_a_missing_input_is_an_input_error(plates, tmp_path):
    with pytest.raises(exrcomp.InputError):
        over(plates, tmp_path / "none.####.exr", tmp_path / "c.####.exr").run(frames="1")


def test_an_unwritable_output_is_an_output_error(plates, tmp_path):
    (tmp_path / "file").write_text("not a folder")
    g = over(plates, plates / "bg.####.exr", tmp_path / "file" / "c.####.exr")
    with pytest.raises(exrcomp.OutputError) as raised:
        g.run(frames="1")
    assert raised.value.exit_code == 4
    assert raised.value.file == str(tmp_path / "file" / "c.0001.exr")
    assert raised.value.frame == 1


def test_bad_graphs_and_settings_are_usage_errors(plates, tmp_path):
    g = exrcomp.Graph()
    with pytest.raises(exrcomp.UsageError, match="takes no parameter 'radiuss'"):
        g.blur(g.read("a.exr"), radiuss=2)
    with pytest.raises(exrcomp.UsageError, match="two inputs"):
        g.over(g.read("b.exr"))
    with pytest.raises(exrcomp.UsageError):
        over(plates, plates / "bg.####.exr", tmp_path / "c.####.exr").run(frames="x-y")
    with pytest.raises(exrcomp.UsageError, match="needs exactly one write|write node"):
        exrcomp.Graph().run(frames="1")
