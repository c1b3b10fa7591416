"""exrcomp.bench returns the record `exrcomp bench --json` writes."""

import json

import pytest

import exrcomp

from conftest import exrcomp as command


def shape(value):
    """A record's keys and kinds of values, not the values."""
    if isinstance(value, dict):
        return {k: shape(v) for k, v in value.items() if k not in ("date", "profile")}
    if isinstance(value, list):
        return [shape(value[0])] if value else []
    return type(value).__name__ if not isinstance(value, (int, float)) else "number"


def test_bench_returns_the_record_of_the_command(plates, tmp_path):
    over = ["over", plates / "fg.####.exr", plates / "bg.####.exr", "-o", "o.####.exr",
            "--frames", "1-2"]
    record = exrcomp.bench(*over, runs=2, warmup=0, name="over", json=tmp_path / "py.json")
    assert record == json.loads((tmp_path / "py.json").read_text())
    assert record["schema"] == "exrcomp-bench-1"
    [job] = record["jobs"]
    assert job["name"] == "over" and job["frames"] == 2
    assert job["command"] == [str(w) for w in over]
    assert len(job["wall_seconds"]["runs"]) == 2
    assert len(job["floor"]["wall_seconds"]["runs"]) == 2
    command("bench", "--runs", 2, "--warmup", 0, "--name", "over", "--json",
            tmp_path / "cli.json", "--", *over)
    assert shape(record) == shape(json.loads((tmp_path / "cli.json").read_text()))


def test_bench_without_a_command_is_a_usage_error():
    with pytest.raises(exrcomp.UsageError, match="give a command to time"):
        exrcomp.bench(runs=1)
    with pytest.raises(exrcomp.UsageError, match="bench takes no setting 'run'"):
        exrcomp.bench("over", run=1)
