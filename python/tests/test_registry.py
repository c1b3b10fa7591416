"""Every operation of the command line is a Graph method taking its
parameters, and the stubs are current: a new op cannot be forgotten."""

import ast
import inspect
import re

import exrcomp
from exrcomp import _stubs

from conftest import exrcomp as command

# The command line's commands that are not operations (a job file's op).
NOT_OPERATIONS = {"flatten", "deepmerge", "farm", "stitch", "run", "transcode",
                  "info", "demo", "bench", "generate", "help"}
# Options every operation's command takes that are not its parameters.
NOT_PARAMETERS = {"help", "output", "threads", "layer", "all_layers", "view", "part",
                  "level", "straight", "json", "progress", "dry_run"}


def commands():
    text = command("--help").stdout
    block = text.split("Commands:")[1].split("\n\n")[0]
    return {line.split()[0] for line in block.splitlines() if line.strip()}


def options(name):
    text = command(name, "--help").stdout
    return {m.replace("-", "_") for m in re.findall(r"^\s+(?:-\w, )?--([\w-]+)", text, re.M)}


def test_every_operation_of_the_command_line_is_a_graph_method():
    ops = commands() - NOT_OPERATIONS
    assert ops == {op["name"] for op in exrcomp.REGISTRY["operations"]}
    for op in exrcomp.REGISTRY["operations"]:
        assert getattr(exrcomp.Graph, op["name"]).__doc__.startswith(op["about"])


def test_every_parameter_of_the_command_line_is_a_graph_key():
    run_write = {k["name"] for k in exrcomp.REGISTRY["run_keys"] + exrcomp.REGISTRY["write_keys"]}
    for op in exrcomp.REGISTRY["operations"]:
        named = {i["name"].replace("-", "_") for i in op["inputs"]}
        given = options(op["name"]) - run_write - NOT_PARAMETERS - named
        assert given == {p["name"] for p in op["params"]}, op["name"]
        cli = options(op["name"])
        assert ("layer" in cli) == op["layers"] and ("straight" in cli) == op["straight"]


def test_a_parameter_is_checked_as_the_command_line_checks_it():
    g = exrcomp.Graph()
    image = g.read("x.####.exr")
    assert g.blur(image, radius=3).name == "blur1"
    try:
        g.blur(image, radius=-1)
    except exrcomp.UsageError as e:
        assert "radius" in str(e)
    else:
        raise AssertionError("a negative radius was taken")


def test_a_python_keyword_is_given_with_an_underscore():
    g = exrcomp.Graph()
    cc = g.colorconvert(g.read("x.exr"), from_="ACEScg", to="ACEScct")
    assert 'from = "ACEScg"' in g.to_toml() and cc.name == "colorconvert1"


def test_the_stubs_are_current():
    path = inspect.getsourcefile(exrcomp).replace("__init__.py", "__init__.pyi")
    with open(path) as f:
        text = f.read()
    assert text == _stubs.text(), "run: python -m exrcomp._stubs > python/exrcomp/__init__.pyi"
    ast.parse(text)
