"""progress is called once a frame, in order, from the calling thread;
KeyboardInterrupt (SIGINT to a child running a graph) stops the run as
Ctrl-C stops the command: complete frames kept, no temporaries left."""

import os
import signal
import subprocess
import sys
import threading
import time

import exrcomp

CHILD = r"""
import sys, exrcomp
plates, out = sys.argv[1], sys.argv[2]
g = exrcomp.Graph()
comp = g.over(g.read(plates + "/fg.####.exr", hold=1), g.read(plates + "/bg.####.exr", hold=1))
g.write(g.blur(comp, radius=60), out + "/c.####.exr")
def progress(frame, done, total):
    print("frame", frame, done, total, flush=True)
try:
    g.run(frames="1-1000", threads=1, progress=progress)
except exrcomp.Interrupted as e:
    print("interrupted:", e, flush=True)
    sys.exit(130)
"""


def test_progress_is_called_once_a_frame_in_order(plates, tmp_path):
    g = exrcomp.Graph()
    g.write(g.over(g.read(str(plates / "fg.####.exr")), g.read(str(plates / "bg.####.exr"))),
            str(tmp_path / "c.####.exr"))
    calls = []
    caller = threading.get_ident()
    g.run(frames="1-4", progress=lambda *call: calls.append((threading.get_ident(), call)))
    assert calls == [(caller, (f, f, 4)) for f in (1, 2, 3, 4)]
    calls.clear()
    assert g.run(frames="1-4", resume=True, progress=lambda *c: calls.append((0, c))) == {
        "kept": [1, 2, 3, 4]}
    assert [c for _, c in calls] == [(f, f, 4) for f in (1, 2, 3, 4)]


def test_a_progress_callbacks_exception_stops_the_run(plates, tmp_path):
    g = exrcomp.Graph()
    g.write(g.read(str(plates / "bg.####.exr"), hold=1), str(tmp_path / "c.####.exr"))

    def fail(frame, done, total):
        raise ValueError(f"stop at {frame}")
    try:
        g.run(frames="1-50", progress=fail)
    except ValueError as e:
        assert str(e) == "stop at 1"
    else:
        raise AssertionError("the callback's exception was lost")
    assert not [p for p in os.listdir(tmp_path) if not p.startswith("c.")]


def test_sigint_keeps_complete_frames_and_no_temporaries(plates, tmp_path):
    out = tmp_path / "out"
    child = subprocess.Popen([sys.executable, "-c", CHILD, str(plates), str(out)],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    first = child.stdout.readline()
    child.send_signal(signal.SIGINT)
    assert first.startswith("frame 1 1 1000"), first
    stdout, stderr = child.communicate(timeout=120)
    assert child.returncode == 130, stdout + stderr
    assert "interrupted: interrupted; no partial frame was left" in stdout
    reported = [int(line.split()[1]) for line in (first + stdout).splitlines()
                if line.startswith("frame ")]
    # Frames the engine finished after the stop are kept too (complete);
    # nothing else is there: no temporary, no partial frame.
    files = sorted(os.listdir(out))
    assert files == [f"c.{f:04}.exr" for f in range(1, len(files) + 1)], files
    assert len(reported) <= len(files) < 1000
    for name in files:
        exrcomp.info(out / name)  # every chunk decodes


def test_the_installed_command_names_itself_to_a_farm(plates, tmp_path):
    # farm (and bench) start exrcomp again: the wheel's script, whose
    # process is Python, must name the script, not the interpreter.
    script = os.path.join(os.path.dirname(sys.executable), "exrcomp")
    assert os.path.exists(script), "the wheel puts exrcomp beside python"
    bundle = tmp_path / "bundle"
    subprocess.run([script, "farm", "openjd", "--threads", "1", "--frames", "1-2",
                    "--bundle", str(bundle), "--", "over", str(plates / "fg.####.exr"),
                    str(plates / "bg.####.exr"), "-o", str(tmp_path / "c.####.exr")],
                   check=True, capture_output=True)
    text = (bundle / "parameter_values.json").read_text()
    assert os.path.abspath(script) in text, text
    assert os.path.realpath(sys.executable) not in text, text


THREADS = r"""
import os, sys, exrcomp
plates, out = sys.argv[1], sys.argv[2]
g = exrcomp.Graph()
g.write(g.read(plates + "/bg.####.exr"), out + "/c.####.exr")
first = int(sys.argv[3]) if len(sys.argv) > 3 else None
g.run(frames="1", threads=first)
g.run(frames="1", threads=first, resume=True)
g.run(frames="1", resume=True)
try:
    g.run(frames="2", threads=3)
except exrcomp.UsageError as e:
    print("refused:", e)
print(sorted(os.listdir(out)))
"""


def test_a_second_thread_count_is_refused_not_ignored(plates, tmp_path):
    # rayon's pool is made once a process: a run asking another count than
    # the first run's (or the default pool's) is an error, never the old count.
    for first, made in (("1", 1), (None, None)):
        out = tmp_path / f"out{first}"
        done = subprocess.run([sys.executable, "-c", THREADS, str(plates), str(out),
                               *([first] if first else [])],
                              capture_output=True, text=True, timeout=120)
        assert done.returncode == 0, done.stderr
        lines = done.stdout.splitlines()
        made = made or len(os.sched_getaffinity(0))  # rayon's default
        if made == 3:
            continue
        assert lines[0] == (f"refused: threads: this process runs its jobs on {made} "
                            "threads (set by its first run, once a process), not 3"), done.stdout
        assert lines[1] == "['c.0001.exr']", done.stdout
