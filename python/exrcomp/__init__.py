"""exrcomp from Python: graphs of the job file's nodes built, checked and run.

A `Graph` holds the nodes of a job file (specs/job-format.md): reads,
operations and one write. Every operation is a method made from its
declaration in the library (`exrcomp._native.registry()`), its help the
docstring; `Graph.to_toml()` is the job file the graph is, and `run` runs
that job file as `exrcomp run` does, so a graph writes what its job file
writes, byte for byte.

    import exrcomp
    g = exrcomp.Graph()
    comp = g.over(g.read("fg.####.exr"), g.read("bg.####.exr"))
    g.write(comp, "comp.####.exr", compression="zip")
    g.run(frames="1001-1100", progress=lambda frame, done, total: print(done, total))
"""

import json as _json
import keyword as _keyword
import math as _math
import os as _os
import shutil as _shutil
import sys as _sys

from . import _native

__all__ = [
    "Graph", "Node", "info", "Error", "UsageError", "InputError",
    "OutputError", "InternalError", "Interrupted", "Regression", "bench", "REGISTRY",
]
__version__ = _native.VERSION

#: The declarations the API is made from: operations, read, write and run keys.
REGISTRY = _json.loads(_native.registry())
_OPS = {op["name"]: op for op in REGISTRY["operations"]}
_READ_KEYS = [k for k in REGISTRY["read_keys"] if k != "read"]
_WRITE_KEYS = {k["name"]: k for k in REGISTRY["write_keys"]}
_RUN_KEYS = {k["name"]: k for k in REGISTRY["run_keys"]}
_BENCH_KEYS = {k["name"]: k for k in REGISTRY["bench_keys"]}


class Error(Exception):
    """An exrcomp error: its message is the command line's (without
    "exrcomp: error: "); `file` and `frame` where the error names them;
    `exit_code` the command line's."""

    exit_code = 1

    def __init__(self, message, file=None, frame=None, exit_code=None):
        super().__init__(message)
        self.file = file
        self.frame = frame
        if exit_code is not None:
            self.exit_code = exit_code


class UsageError(Error):
    """A bad graph, parameter or setting (exit code 2)."""
    exit_code = 2


class InputError(Error):
    """An input missing, damaged or unsupported (exit code 3)."""
    exit_code = 3


class OutputError(Error):
    """An output that could not be written (exit code 4)."""
    exit_code = 4


class InternalError(Error):
    """A bug in exrcomp: please report it with its message (exit code 1)."""


class Interrupted(Error, KeyboardInterrupt):
    """The run was stopped by KeyboardInterrupt (Ctrl-C): complete frames
    are kept, no partial frame is left. A KeyboardInterrupt too."""
    exit_code = 130


class Regression(Error):
    """`bench`: a job slower than the baseline or the other build beyond
    the tolerance and the noise (exit code 1); `record` is the record."""

    def __init__(self, message, record=None):
        super().__init__(message)
        self.record = record


_CLASSES = {"usage": UsageError, "input": InputError, "output": OutputError,
            "interrupted": Interrupted, "internal": InternalError,
            "regression": Regression}


def _native_call(function, *args, **kwargs):
    """`function` called, its `_native.Failure` raised as its class."""
    try:
        return function(*args, **kwargs)
    except _native.Failure as failure:
        kind, message, file, frame, code = failure.args
        raise _CLASSES[kind](message, file, frame, code) from None


def info(path):
    """What `exrcomp info --json PATH` prints for one file, as a dict."""
    return _json.loads(_native_call(_native.info, str(path)))


def _words(what, keys, settings):
    """`settings` (keyword arguments) as the command line's options."""
    words = []
    for key, value in settings.items():
        if key not in keys:
            raise UsageError(f"{what} takes no setting '{key}'" + _suggest(key, list(keys)))
        if value is None or value is False:
            continue
        option = "--" + key.replace("_", "-")
        if value is True:
            words.append(option)
        elif isinstance(value, (list, tuple)):
            words.append(f"{option}={','.join(map(str, value))}")
        else:
            words.append(f"{option}={value}")
    return words


def _own_command():
    """The wheel's `exrcomp` command (beside this Python, else on PATH)."""
    beside = _os.path.join(_os.path.dirname(_sys.executable), "exrcomp")
    found = beside if _os.path.exists(beside) else _shutil.which("exrcomp")
    if not found:
        raise UsageError("bench starts the exrcomp command, which is not installed "
                         "beside this Python or on PATH")
    return _os.path.abspath(found)


def bench(*command, threads=None, **options):
    """Times `command` as `exrcomp bench` does (each run a process of the
    `exrcomp` command the wheel installed, beside a floor, in turns) and
    returns the record `exrcomp bench --json` writes, as a dict. `command`:
    the words after `exrcomp` (`"over", fg, bg, "-o", "o.####.exr"`), or a
    job file; none with `standard=True`. Raises `Regression` (the record
    its `.record`) if a job is slower than `baseline` or `against`.
    `threads`: the timed runs' worker threads. Options (bench's, `_` for
    `-`):
    """
    words = _words("bench", _BENCH_KEYS, options)
    if command:
        words += ["--", *map(_os.fspath, command)]
    text, regression = _native_call(_native.bench, words, _own_command(), threads)
    record = _json.loads(text)
    if regression is not None:
        raise Regression(regression, record)
    return record


class Node:
    """A node of a `Graph`: the input of the operations and the write."""

    __slots__ = ("graph", "name")

    def __init__(self, graph, name):
        self.graph = graph
        self.name = name

    def __repr__(self):
        return f"Node({self.name!r})"


def _suggest(key, allowed):
    """" (it takes: ...)" after an unknown key's message."""
    return f" (it takes: {', '.join(allowed)})" if allowed else " (it takes none)"


def _toml_value(value):
    """A value as TOML writes it (strings, numbers, booleans, lists)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if _math.isnan(value):
            return "nan"
        if _math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_toml_value(v) for v in value) + "]"
    if hasattr(value, "__fspath__"):
        value = value.__fspath__()
    if isinstance(value, str):
        # JSON's string escapes are TOML's basic string's; DEL is escaped too.
        return _json.dumps(value, ensure_ascii=False).replace("\x7f", "\\u007f")
    raise UsageError(f"{value!r} is not a value a job file holds (a string, number, "
                     "boolean or list of them)")


class Graph:
    """The nodes of a job file: `read`, the operations (one method each,
    made from the library's declarations), one `write`; `plan`, `run`,
    `to_toml`, `from_toml`."""

    def __init__(self, frames=None):
        #: The job's frames (the job file's `frames`); `run(frames=...)` wins.
        self.frames = frames
        self._nodes = []
        self._names = set()
        self._counts = {}

    # Nodes.

    def _add(self, kind, table, name, inputs=()):
        if name is None:
            self._counts[kind] = self._counts.get(kind, 0) + 1
            name = f"{kind}{self._counts[kind]}"
            while name in self._names:
                self._counts[kind] += 1
                name = f"{kind}{self._counts[kind]}"
        if name in self._names:
            raise UsageError(f"a node is named '{name}' already")
        names = []
        for node in inputs:
            if not isinstance(node, Node) or node.graph is not self:
                raise UsageError(f"node '{name}': its inputs are nodes of this graph, "
                                 f"not {node!r}")
            names.append(node.name)
        entry = {"name": name}
        entry.update(table)
        if names:
            entry["inputs"] = names
        self._nodes.append(entry)
        self._names.add(name)
        return Node(self, name)

    def read(self, file, *, name=None, **keys):
        """A read node: a file or sequence (`####`, `%04d`), with the job
        file's read keys (`part`, `offset`, `hold`)."""
        for key in keys:
            if key not in _READ_KEYS:
                raise UsageError(f"read takes no key '{key}'" + _suggest(key, _READ_KEYS))
        table = {"read": file}
        table.update({k: v for k, v in keys.items() if v is not None})
        return self._add("read", table, name)

    def write(self, node, file, *, name=None, **keys):
        """The write node (one per graph): the output file or sequence,
        with the job file's write keys (`compression`, `tile`, `attrib`,
        ...: the command line's write options, `_` for `-`)."""
        if any("write" in n for n in self._nodes):
            raise UsageError("a graph has one write node")
        for key in keys:
            if key not in _WRITE_KEYS:
                raise UsageError(f"write takes no key '{key}'" + _suggest(key, list(_WRITE_KEYS)))
        table = {"write": file}
        table.update({k: v for k, v in keys.items() if v is not None and v is not False})
        return self._add("write", table, name, [node])

    def _operation(self, op, inputs, name, params):
        allowed = [p["name"] for p in op["params"]]
        if op["layers"]:
            allowed += REGISTRY["layer_keys"]
        if op["straight"]:
            allowed.append("straight")
        count = len(inputs)
        takes = count >= max(len(op["inputs"]), 2) if op["repeats"] else count == len(op["inputs"])
        if not takes:
            raise UsageError(f"{op['name']} takes {op['arity']}, not {count}")
        table = {"op": op["name"]}
        for key, value in params.items():
            # A key that is a Python keyword (colorconvert's `from`) is
            # given with a trailing underscore, `from_`.
            if key.endswith("_") and _keyword.iskeyword(key[:-1]):
                key = key[:-1]
            if key not in allowed:
                raise UsageError(f"{op['name']} takes no parameter '{key}'" + _suggest(key, allowed))
            if value is None:
                continue
            declared = next((p for p in op["params"] if p["name"] == key), None)
            if declared and not declared["flag"] and not declared["repeats"]:
                text = ",".join(map(str, value)) if isinstance(value, (list, tuple)) else str(value)
                why = _native.check_param(op["name"], key, text)
                if why is not None:
                    raise UsageError(f"{op['name']}: {key}: {why}")
            table[key] = value
        return self._add(op["name"], table, name, inputs)

    # The job file.

    def to_toml(self):
        """The job file this graph is."""
        lines = []
        if self.frames is not None:
            lines.append(f"frames = {_toml_value(str(self.frames))}")
        for node in self._nodes:
            # The name, the kind and the inputs first, then the rest by name:
            # a job file read back writes the same text.
            first = [k for k in ("name", "read", "op", "write", "inputs") if k in node]
            keys = first + sorted(k for k in node if k not in first)
            lines += ["", "[[node]]"]
            lines += [f"{key} = {_toml_value(node[key])}" for key in keys]
        return "\n".join(lines) + "\n"

    @classmethod
    def from_toml(cls, text):
        """The graph of a job file's text (its nodes as they are; `run`
        checks them as `exrcomp run` does)."""
        job = _json.loads(_native_call(_native.toml_to_json, text))
        unknown = set(job) - {"frames", "node"}
        if unknown:
            raise UsageError(f"not a job file key: {', '.join(sorted(unknown))}")
        graph = cls(frames=job.get("frames"))
        for node in job.get("node", []):
            if "name" not in node:
                raise UsageError("a node needs a name")
            graph._nodes.append(dict(node))
            graph._names.add(node["name"])
        return graph

    def node(self, name):
        """The node of this name (of a graph read with `from_toml`)."""
        if name not in self._names:
            raise UsageError(f"no node is named '{name}'")
        return Node(self, name)

    # Running.

    def _settings(self, settings):
        return _words("run", _RUN_KEYS, settings)

    def _run(self, settings, threads=None, progress=None):
        settings.setdefault("quiet", True)
        words = self._settings(settings)
        return _native_call(_native.run_job, self.to_toml(), "graph", words,
                            threads, progress)

    def plan(self, *, threads=None, **settings):
        """What a dry run finds (every check before a pixel is read): a
        dict of `memory` (the most bytes a frame holds at once), `reads`,
        `writes` and `others` (frames at the output another job made).
        Settings: as `run`'s."""
        settings.setdefault("quiet", True)
        return _native_call(_native.run_job, self.to_toml(), "graph",
                            self._settings(settings) + ["--dry-run"], threads, None)

    def run(self, *, threads=None, progress=None, **settings):
        """Runs the graph as `exrcomp run` runs its job file: `progress(frame,
        done, total)` is called from this thread as each frame ends, in the
        order they end; KeyboardInterrupt stops the run as Ctrl-C does
        (raised as `Interrupted`). Returns the frames by what became of
        them ({"written": [...], "kept": [...]}). `threads`: the worker
        threads (set once a process). Settings (the command line's run
        options, `_` for `-`; `quiet` is True unless given):
        """
        return self._run(settings, threads, progress)


def _signature_doc(op):
    """An operation's docstring: its help, inputs and parameters."""
    lines = [op["about"], "", f"Inputs: {op['arity']}: " +
             ", ".join(i["name"] for i in op["inputs"]) + ("..." if op["repeats"] else "")]
    if op["params"] or op["layers"] or op["straight"]:
        lines += ["", "Parameters:"]
    for p in op["params"]:
        extra = " (required)" if p["required"] else (
            f" (default {p['default']})" if p["default"] is not None else "")
        if p["choices"]:
            extra += f" [{', '.join(p['choices'])}]"
        lines.append(f"    {p['name']}{extra}: {p['help'].strip()}")
    if op["layers"]:
        lines.append("    layers, all_layers, view: the layers, views worked on")
    if op["straight"]:
        lines.append("    straight: inputs are not premultiplied")
    return "\n".join(lines)


def _make_operation(op):
    def operation(self, *inputs, name=None, **params):
        return self._operation(op, inputs, name, params)
    operation.__name__ = operation.__qualname__ = op["name"]
    operation.__doc__ = _signature_doc(op)
    return operation


for _op in REGISTRY["operations"]:
    setattr(Graph, _op["name"], _make_operation(_op))

def _keys_doc(keys, indent):
    return "\n".join(f"{indent}{k['name']}: {(k['help'] or '').splitlines()[0]}" for k in keys)


Graph.run.__doc__ += _keys_doc(REGISTRY["run_keys"], " " * 8)
bench.__doc__ += _keys_doc(REGISTRY["bench_keys"], " " * 4)
