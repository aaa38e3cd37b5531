"""The README's code blocks, extracted from the README itself and run, so they cannot drift.

How blocks are chosen, by the language after the opening fence:
- ```python: run with this interpreter;
- ```sh: run with bash -eu -o pipefail (skipped when it draws --pictures and there is no Xvfb);
- ```console: each `$ ` line (with `\\` continuations) is run with bash; the lines after it
  are its expected output (stdout, then stderr), where a line `...` stands for any number of
  lines and `...` inside a line for any text;
- ```text: a command synopsis: every option it names must be in that command's --help;
- ```cmake: every line must be in Testing/Consumer/CMakeLists.txt, the project that
  EndToEnd.consumer_project builds and runs;
- ```tree: the source layout: every path it names (first column, nested by indentation;
  `A/B, C` names A/B and A/C) must exist.
A block whose fence is preceded by the line `<!-- readme-test: skip (REASON) -->` is not run
(set-up commands, long benchmarks, ParaView's packages); any other language fails the test.

Every block runs in a fresh temporary directory holding links to the source's Data/ and
Wrapping/, with this build's `surfacemap` first on PATH and its package on PYTHONPATH,
as the README's set-up section describes.
"""

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from cli import CLI

SOURCE = Path(__file__).resolve().parents[2]
README = SOURCE / "README.md"
SKIP = re.compile(r"^<!-- readme-test: skip \((.+)\) -->$")
FENCE = re.compile(r"^```(\w*)$")
RUN = {"python", "sh", "console", "text", "cmake", "tree"}
TREE_COLUMN = 26
MAX_LINES = 700


def blocks():
    """(first line number, language, code, skip reason or None) of every fenced block."""
    lines = README.read_text().split("\n")
    found, k = [], 0
    while k < len(lines):
        match = FENCE.match(lines[k])
        if not match:
            k += 1
            continue
        start, language = k, match.group(1)
        end = next(j for j in range(k + 1, len(lines)) if lines[j] == "```")
        previous = next((lines[j] for j in range(start - 1, -1, -1) if lines[j].strip()), "")
        skip = SKIP.match(previous)
        found.append((start + 1, language, "\n".join(lines[start + 1:end]) + "\n", skip and skip.group(1)))
        k = end + 1
    return found


BLOCKS = blocks()


def environment():
    env = dict(os.environ)
    env["PATH"] = os.path.dirname(CLI) + os.pathsep + env.get("PATH", "")
    env.pop("DISPLAY", None)  # as on a server: the README's pictures go to the Xvfb they start
    return env


@pytest.fixture
def workdir(tmp_path):
    for name in ("Data", "Wrapping"):
        (tmp_path / name).symlink_to(SOURCE / name)
    return tmp_path


def bash(command, cwd):
    return subprocess.run(["bash", "-eu", "-o", "pipefail", "-c", command], cwd=cwd, env=environment(),
                          capture_output=True, text=True, timeout=600)


def matches(expected, actual):
    """Whether the lines `actual` fit the pattern lines `expected` (see the module's doc)."""
    if not expected:
        return not actual
    if expected[0] == "...":
        return any(matches(expected[1:], actual[k:]) for k in range(len(actual) + 1))
    pattern = ".*".join(re.escape(part) for part in expected[0].split("..."))
    return bool(actual) and re.fullmatch(pattern, actual[0].rstrip()) is not None \
        and matches(expected[1:], actual[1:])


def console_steps(code):
    """(command, expected output lines) of each `$ ` line of a console block."""
    steps, lines = [], code.rstrip("\n").split("\n")
    k = 0
    while k < len(lines):
        assert lines[k].startswith("$ "), f"console output before any command: {lines[k]!r}"
        command = lines[k][2:]
        while command.endswith("\\"):
            k += 1
            command = command[:-1] + " " + lines[k].strip()
        k += 1
        output = []
        while k < len(lines) and not lines[k].startswith("$ "):
            output.append(lines[k])
            k += 1
        steps.append((command, output))
    return steps


def check_block(language, code, cwd):
    if language == "python":
        r = subprocess.run([sys.executable, "-c", code], cwd=cwd, env=environment(), capture_output=True,
                           text=True, timeout=600)
        assert r.returncode == 0, r.stdout + r.stderr
    elif language == "sh":
        if "--pictures" in code and not shutil.which("Xvfb"):
            pytest.skip("Xvfb is not installed (Debian package xvfb)")
        r = bash(code, cwd)
        assert r.returncode == 0, r.stdout + r.stderr
    elif language == "console":
        for command, expected in console_steps(code):
            r = bash(command, cwd)
            actual = (r.stdout + r.stderr).rstrip("\n").split("\n") if r.stdout + r.stderr else []
            assert matches(expected, actual), f"$ {command}\nexpected:\n" + "\n".join(expected) + \
                "\nactual:\n" + "\n".join(actual)
    elif language == "text":
        helps = {}
        for line in code.split("\n"):
            if line.startswith("surfacemap "):
                command = line.split()[1]
                helps[command] = subprocess.run([CLI, command, "--help"], capture_output=True, text=True).stdout
                assert helps[command], f"surfacemap {command} --help printed nothing"
            for option in re.findall(r"(?<![\w-])(--?[a-z][a-z-]*)", line):
                assert re.search(rf"(?<![\w-]){re.escape(option)}(?![\w-])", helps[command]), \
                    f"surfacemap {command} --help does not name {option}"
    elif language == "cmake":
        consumer = (SOURCE / "Testing" / "Consumer" / "CMakeLists.txt").read_text().split("\n")
        for line in code.split("\n"):
            assert not line.strip() or line in consumer, f"not in Testing/Consumer/CMakeLists.txt: {line}"
    elif language == "tree":
        for path in tree_paths(code):
            assert (SOURCE / path).exists(), f"the layout names {path}, which does not exist"


def tree_paths(code):
    """The paths a layout block names: its first column, nested by two-space indentation."""
    parents, paths = [], []  # parents[level]: the path of the last entry at that level
    for line in code.split("\n"):
        head = line[:TREE_COLUMN].rstrip()
        if not head:
            continue
        level = (len(head) - len(head.lstrip())) // 2
        names = [n.strip().rstrip("/") for n in head.strip().split(",")]
        first = (parents[level - 1] if level else Path()) / names[0]
        paths += [first] + [first.parent / n for n in names[1:]]
        parents = parents[:level] + [first]
    return paths


@pytest.mark.parametrize("line, language, code, skip", BLOCKS,
                         ids=[f"line{b[0]}-{b[1] or 'plain'}" for b in BLOCKS])
def test_block(line, language, code, skip, workdir):
    assert language in RUN or skip, f"README line {line}: a ```{language} block the test cannot run; " \
        "use one of " + ", ".join(sorted(RUN)) + " or mark it <!-- readme-test: skip (REASON) -->"
    if skip:
        pytest.skip(skip)
    check_block(language, code, workdir)


def test_the_readme_is_a_short_guide():
    assert len(README.read_text().split("\n")) - 1 <= MAX_LINES


def test_the_matcher_accepts_and_refuses():
    assert matches(["a ...", "...", "c"], ["a b", "x", "y", "c"])
    assert matches(["...", "b"], ["b"])
    assert not matches(["a ...", "c"], ["a b", "x", "c"])
    assert not matches(["a"], ["a", "b"])
