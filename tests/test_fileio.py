"""Reading user files into clear errors; writing outputs whole or not at all."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from seal_cli.errors import SealError
from seal_cli.fileio import (
    atomic_output,
    atomic_write_text,
    json_value,
    read_json,
    read_json_lines,
    read_text,
    read_yaml,
    typed,
)


def test_written_files_get_the_usual_mode(tmp_path: Path) -> None:
    target = tmp_path / "out.txt"
    atomic_write_text(target, "hello")
    mask = os.umask(0)
    os.umask(mask)
    assert target.read_text() == "hello"
    assert target.stat().st_mode & 0o777 == 0o666 & ~mask


def test_a_failure_leaves_nothing_behind(tmp_path: Path) -> None:
    target = tmp_path / "out.png"
    with pytest.raises(RuntimeError), atomic_output(target) as tmp:
        tmp.write_bytes(b"half")
        raise RuntimeError("drawing failed")
    assert list(tmp_path.iterdir()) == []


def test_an_existing_file_survives_a_failed_rewrite(tmp_path: Path) -> None:
    target = tmp_path / "out.txt"
    target.write_text("old")
    with pytest.raises(RuntimeError), atomic_output(target) as tmp:
        tmp.write_text("new")
        raise RuntimeError
    assert target.read_text() == "old"


def test_missing_folder_is_a_clear_error(tmp_path: Path) -> None:
    with pytest.raises(SealError, match="folder .* does not exist"), atomic_output(tmp_path / "no" / "x.rrd"):
        pass


def test_reading_errors_name_the_file(tmp_path: Path) -> None:
    with pytest.raises(SealError, match="no such file"):
        read_text(tmp_path / "missing.yaml")
    with pytest.raises(SealError, match="is a folder"):
        read_text(tmp_path)
    binary = tmp_path / "b.yaml"
    binary.write_bytes(b"\xff\xfe\x00")
    with pytest.raises(SealError, match="not UTF-8"):
        read_text(binary)


def test_yaml_syntax_errors_carry_line_column_and_caret(tmp_path: Path) -> None:
    bad = tmp_path / "bad.yaml"
    bad.write_text("poses:\n  - [1, 2\n  - [3, 4]\n")
    with pytest.raises(SealError) as caught:
        read_yaml(bad)
    assert caught.value.line == 3 and caught.value.file == str(bad)
    assert str(caught.value).splitlines()[-1].endswith("^")


def test_a_folder_as_the_output_is_a_clear_error(tmp_path: Path) -> None:
    with pytest.raises(SealError, match="is a folder"), atomic_output(tmp_path):
        pass
    assert list(tmp_path.iterdir()) == []


def test_localize_png_onto_a_folder_is_exit_1_and_leaves_nothing(tmp_path: Path) -> None:
    from typer.testing import CliRunner

    from seal_cli.cli import app

    out = tmp_path / "out"
    out.mkdir()
    for option in ("--png", "--rrd"):
        result = CliRunner().invoke(app, ["localize", "--map", "apartment", "--steps", "1", "--particles", "10",
                                          option, str(out)])
        assert result.exit_code == 1, result.output
        assert "is a folder" in result.stderr and str(out) in result.stderr
        assert "Traceback" not in result.stderr
        assert list(out.iterdir()) == [] and sorted(p.name for p in tmp_path.iterdir()) == ["out"]


def test_json_lines_errors_carry_line_and_column(tmp_path: Path) -> None:
    from seal_cli.fileio import read_json_lines

    path = tmp_path / "c.jsonl"
    path.write_text('{"a": 1}\n\n{"b": nope}\n', encoding="utf-8")
    with pytest.raises(SealError) as info:
        read_json_lines(path)
    assert (info.value.line, info.value.column) == (3, 7) and "not JSON" in info.value.message
    path.write_text('{"a": 1}\n\n[2]\n', encoding="utf-8")
    assert read_json_lines(path) == [{"a": 1}, [2]]


@pytest.mark.parametrize(("text", "line", "column"), [("a: 1\nb: [x,\x00 y]\n", 2, 7), ("a: 1\rb: \x01\r", 2, 4),
                                                     ("\x07", 1, 1)])
def test_a_control_character_yaml_refuses_is_located(tmp_path: Path, text: str, line: int, column: int) -> None:
    path = tmp_path / "c.yaml"
    path.write_text(text, newline="")
    with pytest.raises(SealError) as caught:
        read_yaml(path)
    assert (caught.value.line, caught.value.column) == (line, column)
    assert "control character" in caught.value.message and "<unicode string>" not in str(caught.value)


def test_a_dash_for_an_output_is_refused_not_written_as_a_file(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """``--png -`` would write a file called "-"; seal's outputs are files (or folders), never standard output."""
    from seal_cli.fileio import Outputs

    monkeypatch.chdir(tmp_path)
    with pytest.raises(SealError, match=r"--png '-': seal writes this output into a file, not to standard output"):
        Outputs({"--png": "-"})
    with pytest.raises(SealError, match=r"--pddl ' ': seal writes this output into a folder"):
        Outputs({"--pddl": " "}, folders={"--pddl": ("domain.pddl",)})
    assert list(tmp_path.iterdir()) == []


def test_json_errors_are_at_their_line_and_column(tmp_path: Path) -> None:
    from seal_cli.fileio import read_json

    path = tmp_path / "f.json"
    path.write_text('{"a": 1,\n "b": }\n')
    with pytest.raises(SealError, match=r"f\.json:2:7: this JSON file is not JSON: Expecting value") as caught:
        read_json(path)
    assert caught.value.source_line == ' "b": }'
    path.write_text("[" * 100_000 + "]" * 100_000)
    with pytest.raises(SealError, match="nested too deeply"):
        read_json(path)


def test_streamed_lines_are_refused_by_kind_and_decoded_at_their_line(tmp_path: Path) -> None:
    from seal_cli.fileio import stream_lines

    path = tmp_path / "t.jsonl"
    path.write_bytes(b"\xef\xbb\xbfone\ntwo\r\nthr\xe9e\n")
    lines = stream_lines(path, "trials file")
    assert [next(lines), next(lines)] == [(1, "one\n"), (2, "two\r\n")]
    with pytest.raises(SealError, match=r"t\.jsonl:3:4: this trials file is not UTF-8 text: byte 0xe9"):
        next(lines)
    fifo = tmp_path / "p.jsonl"
    os.mkfifo(fifo)
    with pytest.raises(SealError, match="it is a FIFO"):
        next(stream_lines(fifo))
    with pytest.raises(SealError, match="no such file"):
        next(stream_lines(tmp_path / "none.jsonl"))


def test_a_file_that_waits_for_data_is_not_waited_on() -> None:
    kmsg = Path("/proc/kmsg")  # a regular file by its kind whose read blocks (readable by root only)
    if not os.access(kmsg, os.R_OK):
        pytest.skip("/proc/kmsg cannot be read here")
    try:
        read_text(kmsg)
    except SealError as error:
        assert "kmsg" in str(error)


def test_an_integer_of_more_digits_than_python_converts_is_a_located_yaml_error(tmp_path: Path) -> None:
    path = tmp_path / "v.yaml"
    path.write_text("- cup\n- " + "1" * 5_000 + "\n")
    with pytest.raises(SealError, match=r"v\.yaml:2:3: .*an integer of 5,000 digits") as caught:
        read_yaml(path)
    assert len(str(caught.value).splitlines()[0]) < 200  # the value is not printed whole
    path.write_text("- " + "1" * 4_000 + "\n- 0x" + "f" * 5_000 + "\n")  # within the bound; hex is not limited
    assert read_yaml(path)[0] == int("1" * 4_000)


def test_a_file_with_more_values_than_asked_is_refused_at_the_value_past_the_bound(tmp_path: Path) -> None:
    path = tmp_path / "v.yaml"
    path.write_text("".join(f"- w{k}\n" for k in range(1_000)))
    assert len(read_yaml(path, max_values=1_001)) == 1_000  # the list and its 1,000 words
    with pytest.raises(SealError, match=r"v\.yaml:500:3: this vocabulary holds more than 500 values"):
        read_yaml(path, max_values=500, what="vocabulary")


def test_an_interrupt_python_cannot_raise_is_noted_silently(capfd: pytest.CaptureFixture[str]) -> None:
    """A SIGINT whose KeyboardInterrupt lands where Python cannot raise it (here a ``__del__``; in a run, a ctypes
    callback of LLVM's while numba compiles) was printed as "Exception ignored ... Traceback" and dropped, and the
    command ran on; now nothing is printed and the signal is sent again, raised where Python runs next."""
    import signal
    import sys

    from seal_cli import fileio

    hook = sys.unraisablehook
    try:
        sys.unraisablehook = sys.__unraisablehook__          # Python's own (pytest's makes it a warning)
        signal.signal(signal.SIGINT, signal.default_int_handler)  # pytest started in the background ignores SIGINT
        fileio.note_interrupts()

        class Dropper:
            def __del__(self) -> None:
                signal.raise_signal(signal.SIGINT)   # the handler runs here, inside __del__
                for _ in range(1000):               # ... at the next bytecode
                    pass

        with pytest.raises(KeyboardInterrupt):   # sent again: raised where Python runs then, here
            Dropper()
            import time

            time.sleep(1.0)
        assert fileio.interrupted()
        assert "Traceback" not in capfd.readouterr().err
    finally:
        signal.signal(signal.SIGINT, signal.default_int_handler)
        sys.unraisablehook = hook
        fileio._INTERRUPTED[0] = False


def test_an_error_in_a_del_after_an_interrupt_is_its_echo_not_printed(capfd: pytest.CaptureFixture[str]) -> None:
    """An object an interrupt left half built fails in its ``__del__`` (llvmlite's ``PassBuilder`` interrupted while
    numba compiled: "Exception ignored ... AttributeError"): dropped once SIGINT has come, printed before it."""
    import sys

    from seal_cli import fileio

    class HalfBuilt:
        def __del__(self) -> None:
            raise AttributeError("'HalfBuilt' object has no attribute '_as_parameter_'")

    hook = sys.unraisablehook
    try:
        sys.unraisablehook = sys.__unraisablehook__
        fileio.note_interrupts()
        HalfBuilt()
        assert "_as_parameter_" in capfd.readouterr().err     # no interrupt yet: Python's own message
        fileio._INTERRUPTED[0] = True
        HalfBuilt()
        assert capfd.readouterr().err == ""
    finally:
        sys.unraisablehook = hook
        fileio._INTERRUPTED[0] = False


def test_text_is_read_composed_so_a_decomposed_name_is_the_composed_one(tmp_path: Path) -> None:
    """macOS writes "é" as "e" + U+0301: a map or a command file in that form named rooms no command could reach
    ("the apartment has no caf"); files are read in NFC, which leaves composed and ASCII text as it is."""
    from seal_cli.fileio import composed

    (tmp_path / "m.yaml").write_text("rooms: [cafe\u0301]\n", encoding="utf-8")
    assert read_text(tmp_path / "m.yaml") == "rooms: [caf\u00e9]\n"
    assert read_yaml(tmp_path / "m.yaml") == {"rooms": ["caf\u00e9"]}
    assert composed("plain") == "plain" and composed("caf\u00e9") == "caf\u00e9"


def test_outputs_of_a_command_whose_interrupt_was_dropped_are_not_written(tmp_path: Path,
                                                                        monkeypatch: pytest.MonkeyPatch) -> None:
    from seal_cli import fileio

    monkeypatch.setattr(fileio, "_INTERRUPTED", [True])      # noted, never raised
    outputs = fileio.Outputs({"--png": tmp_path / "o.png"}, suffixes={"--png": (".png",)})
    outputs["--png"].write_bytes(b"x")
    with pytest.raises(KeyboardInterrupt):
        outputs.commit()
    assert sorted(p.name for p in tmp_path.iterdir()) == []


def test_compose_yaml_gives_nodes_and_words_a_syntax_error_at_its_line_and_column() -> None:
    import yaml

    from seal_cli.errors import SealError
    from seal_cli.fileio import compose_yaml

    assert isinstance(compose_yaml("a: [1, 2]\n", "f.yaml"), yaml.MappingNode)
    assert compose_yaml("", "f.yaml") is None
    with pytest.raises(SealError) as caught:
        compose_yaml("a: 1\nb: [2\n", "f.yaml")
    assert "YAML syntax error" in str(caught.value) and caught.value.where.line == 3


def test_an_output_read_as_an_input_after_it_was_planned_is_not_written(tmp_path: Path) -> None:
    # bench tasks --episodes d/floorplans.json: the data was read as the episodes ran, after --episodes was
    # planned, and the JSON Lines replaced it (hostile16)
    from seal_cli.fileio import Outputs, read_bytes

    data = tmp_path / "floorplans.json"
    data.write_text('{"floor_plans": {}}\n')
    said = r"--episodes .*floorplans\.json would overwrite the input .*which the command read"
    with pytest.raises(SealError, match=said), Outputs({"--episodes": data}) as outputs:
        read_bytes(data)
        outputs["--episodes"].write_text("{}\n")
    assert data.read_text() == '{"floor_plans": {}}\n'
    assert sorted(p.name for p in tmp_path.iterdir()) == ["floorplans.json"]   # no temporary left


def test_the_alfred2d_data_files_are_inputs_of_bench_tasks(tmp_path: Path) -> None:
    from seal_cli.bench.alfred2d import data_files

    for name in ("floorplans.json", "trials_train.jsonl", "trials_valid_seen.jsonl", "notes.txt"):
        (tmp_path / name).write_text("")
    assert [p.name for p in data_files(tmp_path)] == ["floorplans.json", "trials_train.jsonl",
                                                      "trials_valid_seen.jsonl"]


def test_composing_counts_the_values_before_it_builds_a_node(monkeypatch: pytest.MonkeyPatch) -> None:
    # a 14 MB map of seven million numbers composed for over a minute and 2 GB before anything looked at it
    # (hostile17): every composed reader is bounded as read_yaml is, at the value past the bound
    import yaml

    from seal_cli import yamlnodes
    from seal_cli.fileio import compose_documents, compose_yaml

    monkeypatch.setattr(yamlnodes, "MAX_VALUES", 10)
    built: list[str] = []
    monkeypatch.setattr(yaml, "compose", lambda *a, **k: built.append("compose"))
    with pytest.raises(SealError, match="holds more than 10 values") as caught:
        compose_yaml("a: [" + ", ".join("0" * 20) + "]\n", "m.yaml")
    assert (caught.value.where.line, caught.value.where.column) == (1, 26) and built == []  # the 11th value
    monkeypatch.undo()
    monkeypatch.setattr(yamlnodes, "MAX_VALUES", 30)  # 19 values as written, 48 expanded
    bomb = "a: &a [x, x, x]\nb: &b [*a, *a, *a]\nc: [*b, *b]\n"
    with pytest.raises(SealError, match="once its aliases"):
        compose_documents("---\n{}\n---\n" + bomb, "f.yaml")
    assert [type(d).__name__ for d in compose_documents("---\n[1]\n---\n{}\n", "f.yaml")] == ["SequenceNode",
                                                                                              "MappingNode"]


def test_a_file_just_past_the_bound_says_its_size_in_bytes(tmp_path: Path) -> None:
    # "this file is 16 MiB; seal reads files of at most 16 MiB" (hostile17)
    from seal_cli.fileio import read_bytes

    (tmp_path / "o.yaml").write_bytes(b"#" * (2**20 + 100))
    with pytest.raises(SealError, match=r"is 1,048,676 bytes; seal reads files of at most 1,048,576 bytes \(1 MiB\)"):
        read_bytes(tmp_path / "o.yaml", 2**20)
    (tmp_path / "o.yaml").write_bytes(b"#" * (3 * 2**19))
    with pytest.raises(SealError, match=r"is 1\.5 MiB; seal reads files of at most 1 MiB$"):
        read_bytes(tmp_path / "o.yaml", 2**20)


def test_a_full_disk_under_an_output_is_said_of_its_option(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # a full disk said "cannot write the output" (as if stdout had failed) or named the temporary (hostile17)
    import errno
    import os

    from seal_cli.fileio import Outputs, atomic_output

    class Full:
        f_bavail = 0

    monkeypatch.setattr(os, "statvfs", lambda folder: Full())
    png = {"--png": tmp_path / "o.png"}
    said = r"^cannot write --png .*o\.png: No space left on device$"
    with pytest.raises(SealError, match=said), Outputs(png, suffixes={"--png": (".png",)}):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
    with pytest.raises(SealError, match=said), Outputs(png, suffixes={"--png": (".png",)}) as outputs, \
            atomic_output(outputs["--png"]) as inner:  # a writer's own temporary, inside the command's
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(inner))
    with pytest.raises(OSError, match="Broken pipe"), Outputs(png, suffixes={"--png": (".png",)}):
        raise OSError(errno.EPIPE, os.strerror(errno.EPIPE))  # anything else is left to the CLI, as it was
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(("data", "wide"), [
    ("stir the cup\n".encode("utf-16"), "UTF-16"), ("stir the cup\n".encode("utf-16-be"), "UTF-16"),
    ("stir the cup\n".encode("utf-16-le"), "UTF-16"), ("stir the cup\n".encode("utf-32"), "UTF-32"),
])
def test_a_text_in_a_wide_encoding_is_named_as_such(tmp_path: Path, data: bytes, wide: str) -> None:
    """hostile19: UTF-16 said 'byte 0xff cannot be decoded' (with its mark) or read NULs as letters (without)."""
    from seal_cli.fileio import stream_lines

    path = tmp_path / "c.txt"
    path.write_bytes(data)
    with pytest.raises(SealError, match=rf"c\.txt:1:1: this file is {wide} text, not UTF-8: .*as UTF-8") as caught:
        read_text(path)
    assert (caught.value.where.line, caught.value.where.column) == (1, 1)
    with pytest.raises(SealError, match=rf"is {wide} text, not UTF-8"):
        list(stream_lines(path))


def test_utf8_with_a_nul_is_no_wide_text(tmp_path: Path) -> None:
    from seal_cli.fileio import wide_encoding

    assert wide_encoding(b"stir\x00 the cup\n") is None and wide_encoding(b"\xef\xbb\xbfstir") is None
    assert wide_encoding(b"\xff\xfe") == "UTF-16" and wide_encoding(b"a\x00b\x00c\x00") == "UTF-16"


def test_a_stream_handed_to_the_command_says_how_to_read_it() -> None:
    """hostile19: `echo ... | seal parse --file /dev/stdin` and `--file <(...)` said only "it is a FIFO"."""
    import subprocess
    import sys

    done = subprocess.run([sys.executable, "-m", "seal_cli", "parse", "--file", "/dev/stdin"], input=b"stir the cup\n",
                          capture_output=True, timeout=120, check=False)
    assert done.returncode == 1
    assert b"a stream this command was handed" in done.stderr and b"seal parse --file -" in done.stderr


def test_an_output_past_ulimit_f_is_said_of_its_option(tmp_path: Path) -> None:
    # a file grown past RLIMIT_FSIZE said "cannot write the output", as if stdout had failed (hostile20); run in a child
    # process, whose limit is its own
    script = (
        "import resource, sys\n"
        "from pathlib import Path\n"
        "from seal_cli.errors import SealError\n"
        "from seal_cli.fileio import Outputs\n"
        "resource.setrlimit(resource.RLIMIT_FSIZE, (4096, 4096))\n"
        "folder = Path(sys.argv[1])\n"
        "try:\n"
        "    with Outputs({'--png': folder / 'o.png', '--rrd': folder / 'o.rrd'},\n"
        "                 suffixes={'--png': ('.png',), '--rrd': ('.rrd',)}) as outputs:\n"
        "        outputs['--rrd'].write_bytes(b'r' * 100)\n"
        "        with open(outputs['--png'], 'wb') as f:\n"
        "            f.write(b'p' * 10_000)\n"
        "except SealError as error:\n"
        "    print(error)\n")
    env = {**os.environ, "PYTHONPATH": str(Path(__file__).resolve().parents[1])}
    done = subprocess.run([sys.executable, "-c", script, str(tmp_path)], capture_output=True, text=True, check=False,
                          env=env)
    assert done.stderr == ""
    assert re.fullmatch(r"cannot write --png .*o\.png: File too large\n", done.stdout)
    assert list(tmp_path.iterdir()) == []  # neither output written, no temporary left


@pytest.mark.parametrize(("value", "said"), [
    ("010", r"'010' has a leading zero: YAML 1\.1, which seal reads, takes it as octal \(8\), YAML 1\.2, which ROS "
            r"reads, as 10"),
    ("-012", r"'-012' has a leading zero: .* octal \(-10\), .* as -12"),
    ("10:00", r"'10:00' is a number in base 60 to YAML 1\.1"),
    ("1:30.5", r"'1:30\.5' is a number in base 60"),
])
def test_a_number_yaml_11_and_12_read_otherwise_is_refused_at_its_place(tmp_path: Path, value: str, said: str) -> None:
    # bounds: [0, 0, 10:00, 10] made a map 600 m wide, 012 10 m: YAML 1.1's readings, not ROS's (hostile21)
    path = tmp_path / "m.yaml"
    path.write_text(f"a: 1\nb: [0, {value}]\n")
    with pytest.raises(SealError, match=r"m\.yaml:2:8: cannot read this value: " + said):
        read_yaml(path)


def test_a_number_both_yamls_read_alike_is_read(tmp_path: Path) -> None:
    path = tmp_path / "m.yaml"
    path.write_text("[07, -05, 00, 0, 0x10, 1_000, 10.5, '10:00', '010', 0.5]\n")
    assert read_yaml(path) == [7, -5, 0, 0, 16, 1000, 10.5, "10:00", "010", 0.5]


def test_a_dash_that_is_no_file_says_where_standard_input_is_read(tmp_path: Path,
                                                                  monkeypatch: pytest.MonkeyPatch) -> None:
    # `bench plan --file -` said only "-: no such file" where `parse --file -` reads standard input (hostile21)
    monkeypatch.chdir(tmp_path)
    with pytest.raises(SealError, match=r"^-: no such file \('-' is standard input only to seal parse --file"):
        read_text("-")
    (tmp_path / "-").write_text("stir the cup\n")     # a file called '-' is a file
    assert read_text("-") == "stir the cup\n"


def test_a_command_line_text_is_read_as_its_user_typed_it() -> None:
    # the bytes of "café" that an ASCII locale could not decode (surrogateescape) are UTF-8: read so (hostile21)
    undecoded = "stir the caf\udcc3\udca9"
    assert typed(undecoded) == "stir the café" and typed("stir the cafe\u0301") == "stir the café"
    assert typed("stir the caf\udce9") == "stir the caf\udce9"     # no UTF-8: left for the parser to name
    assert typed("stir the cup") == "stir the cup"


@pytest.mark.parametrize("argv", [["parse", "stir the cafe\u0301"], ["parse", "stir the cafe\u0301", "--json"]])
def test_seal_parse_text_without_typer_composes_and_reads_utf8_in_an_ascii_locale(argv: list[str]) -> None:
    """``seal parse TEXT`` (answered without typer) took the text as given: decomposed it was refused at the accent
    where ``seal plan`` read it, and in an ASCII locale (``LANG=C``, Python's UTF-8 mode off) every accented letter
    was refused (hostile21)."""
    import os
    import subprocess
    import sys

    for env in ({}, {"LC_ALL": "C", "LANG": "C", "PYTHONUTF8": "0", "PYTHONCOERCECLOCALE": "0"}):
        done = subprocess.run([sys.executable, "-m", "seal_cli", *argv], capture_output=True, timeout=120, check=False,
                              env={**os.environ, **env})
        assert done.returncode == 0, (env, done.stderr)
        assert b"Stir" in done.stdout and (b"caf" in done.stdout)


def test_a_signal_just_as_a_temporary_is_made_still_leaves_nothing_behind(tmp_path: Path) -> None:
    """An interrupt landing between the temporary's creation and its recording left it behind (CI: "a signal 15
    while run --png --rrd writes its temporary", the judge signalling as soon as the temporary appears): the two
    are one step now, the signal acted on once the temporary is known. In a process of its own (a real SIGINT)."""
    code = (
        "import os, signal, sys\n"
        "import seal_cli.fileio as fileio\n"
        "real = os.close\n"
        "def close(fd):\n"
        "    real(fd)\n"
        "    os.kill(os.getpid(), signal.SIGINT)\n"
        "os.close = close\n"
        "try:\n"
        "    fileio.Outputs({'--png': sys.argv[1]}, suffixes={'--png': ('.png',)})\n"
        "except KeyboardInterrupt:\n"
        "    os.close = real\n"
        "    fileio.remove_temporaries()\n"
        "    print('interrupted')\n")
    run = subprocess.run([sys.executable, "-c", code, str(tmp_path / "o.png")], capture_output=True, text=True,
                         timeout=60)
    assert run.stdout.strip() == "interrupted", run.stderr
    assert list(tmp_path.iterdir()) == []


def test_a_device_that_fails_leaves_the_other_outputs_unwritten(tmp_path: Path) -> None:
    """Devices are written before the renames: ``run --png /dev/full --rrd o.rrd`` failed on /dev/full with o.rrd
    already in place (hostile25: "a failed command left o.rrd")."""
    from seal_cli.fileio import Outputs

    with pytest.raises(SealError, match="cannot write --png /dev/full: No space left on device"), \
            Outputs({"--rrd": tmp_path / "o.rrd", "--png": "/dev/full"}) as plan:
        plan["--rrd"].write_bytes(b"rrd")
        plan["--png"].write_bytes(b"png")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("ignored", [True, False])
def test_a_signal_started_ignored_stays_ignored(tmp_path: Path, ignored: bool) -> None:
    """``nohup seal run ...`` starts seal with SIGHUP ignored; seal's handler replaced that, and the run ended with
    exit code 129 when the terminal closed (hostile25). Not ignored, SIGHUP still ends the command by an exception,
    its temporaries removed. In a process of its own."""
    code = (
        "import os, signal, sys\n"
        f"signal.signal(signal.SIGHUP, signal.SIG_IGN if {ignored} else signal.SIG_DFL)\n"
        "import seal_cli.fileio as fileio\n"
        "fileio.clean_up_on_signals()\n"
        "with fileio.Outputs({'--png': sys.argv[1]}) as plan:\n"
        "    os.kill(os.getpid(), signal.SIGHUP)\n"
        "    plan['--png'].write_bytes(b'png')\n"
        "print('written')\n")
    run = subprocess.run([sys.executable, "-c", code, str(tmp_path / "o.png")], capture_output=True, text=True,
                         timeout=60)
    if ignored:
        assert (run.returncode, run.stdout.strip()) == (0, "written") and (tmp_path / "o.png").read_bytes() == b"png"
    else:
        assert run.returncode == 129 and list(tmp_path.iterdir()) == [], run.stderr


def test_a_path_is_shown_with_what_cannot_be_printed_escaped() -> None:
    """A newline, an escape or a byte that was not UTF-8 in an output's name is shown as its escape: the message
    stays one line and says nothing to the terminal (hostile26)."""
    from seal_cli.fileio import shown_path

    assert shown_path("a b/ç😀.png") == "a b/ç😀.png"
    assert shown_path("x\ny\x1b[2J\udcff.png") == "x\\ny\\x1b[2J\\xff.png"


def test_a_wrong_suffix_with_a_newline_is_said_on_one_line(tmp_path: Path) -> None:
    from seal_cli.fileio import Outputs

    with pytest.raises(SealError) as caught:
        Outputs({"--rrd": tmp_path / "x\ny.png"}, suffixes={"--rrd": (".rrd",)})
    assert "\n" not in str(caught.value) and "x\\ny.png" in str(caught.value)


def test_a_folder_removed_while_an_output_is_written_is_said_of_its_option(tmp_path: Path) -> None:
    """The folder of ``--png d/o.png`` removed while the command runs: the writer nested in the output (the picture's
    own ``atomic_output`` of the temporary) leaves the message to the output, which names ``--png`` and the folder
    (hostile26: "cannot write output d/.o.png.seal…tmp.png: folder d does not exist"); nothing is left behind."""
    import shutil

    from seal_cli.fileio import Outputs

    folder = tmp_path / "d"
    folder.mkdir()
    with pytest.raises(SealError, match=r"^cannot write --png .*d/o\.png: folder .*d does not exist$"), \
            Outputs({"--png": folder / "o.png"}) as plan:
        shutil.rmtree(folder)
        with atomic_output(plan["--png"]) as tmp:
            tmp.write_bytes(b"x")
    assert not folder.exists()
    folder.mkdir()
    with pytest.raises(SealError, match=r"^cannot write --png .*d/o\.png: folder .*d does not exist$"), \
            Outputs({"--png": folder / "o.png"}) as plan:
        plan["--png"].write_bytes(b"x")
        shutil.rmtree(folder)                   # gone before the rename
    with pytest.raises(SealError, match="folder .* does not exist"), atomic_output(tmp_path / "no" / "x.png"):
        pass                                    # alone, atomic_output names its own target, as it always did


def test_a_work_folder_carries_the_process_id_and_a_dead_one_s_is_swept(tmp_path: Path) -> None:
    """A writer that builds its output in a folder (a bag) gets one named as a temporary of the target, with this
    process's id; a folder of a process that no longer runs is removed, with what it holds (hostile27: a killed
    ``--goals g.mcap`` left ``tempfile.mkdtemp``'s ``.g.mcap.2x8f_k1`` for ever)."""
    from seal_cli.fileio import work_folder

    dead = tmp_path / ".g.mcap.seal999999-0123abcd.tmp"
    (dead / "out").mkdir(parents=True)
    (dead / "out" / "half.mcap").write_bytes(b"half")
    mine = work_folder(tmp_path / "g.mcap")
    assert mine.is_dir() and mine.name.startswith(f".g.mcap.seal{os.getpid()}-") and mine.name.endswith(".tmp")
    assert not dead.exists()
    other = work_folder(tmp_path / "g.mcap")    # this process's own are live: never swept
    assert mine.exists() and other != mine


@pytest.mark.parametrize(("text", "column"), [('{"a": "x\\ud800"}', 9), ('{"a": ["\\udc80"]}', 9),
                                              ('{"\\ud800": 1}', 3), ('{"a": "\\ud83d"}', 8)])
def test_a_json_escape_of_half_a_character_is_refused_at_its_column(tmp_path: Path, text: str, column: int) -> None:
    # hostile28: json decodes "\ud800" to a lone surrogate, which failed at its first write (UnicodeEncodeError)
    from seal_cli.fileio import read_json, read_json_lines

    path = tmp_path / "f.json"
    path.write_text(text + "\n", encoding="utf-8")
    with pytest.raises(SealError, match="is half a character") as caught:
        read_json(path)
    assert (caught.value.where.line, caught.value.where.column) == (1, column)
    path.write_text('{"a": 1}\n\n' + text + "\n", encoding="utf-8")
    with pytest.raises(SealError, match="lone surrogate") as caught:
        read_json_lines(path)
    assert (caught.value.where.line, caught.value.where.column) == (3, column)


def test_whole_characters_written_as_escapes_or_pairs_pass(tmp_path: Path) -> None:
    from seal_cli.fileio import read_json

    path = tmp_path / "f.json"
    path.write_text('{"a": "\\ud83d\\ude00 caf\\u00e9", "b": "\\\\ud800 is text"}', encoding="utf-8")
    assert read_json(path) == {"a": "😀 café", "b": "\\ud800 is text"}


def test_a_deleted_working_folder_is_named_for_a_relative_name(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # hostile28: "cannot write the output: No such file or directory", "c.txt: no such file"
    from seal_cli.fileio import Outputs, cwd_gone, gone_cwd_hint

    gone = tmp_path / "gone"
    gone.mkdir()
    monkeypatch.chdir(gone)
    assert not cwd_gone() and gone_cwd_hint("c.txt") == ""
    gone.rmdir()
    assert cwd_gone() and "working folder has been deleted" in gone_cwd_hint("c.txt")
    assert gone_cwd_hint(tmp_path / "c.txt") == ""     # an absolute name names what it always named
    with pytest.raises(SealError, match=r"^c\.txt: no such file \(the working folder has been deleted"):
        read_text("c.txt")
    with pytest.raises(SealError, match=r"cannot write --png o\.png: the working folder has been deleted"):
        Outputs({"--png": "o.png"}, suffixes={"--png": (".png",)})
    with Outputs({"--png": tmp_path / "o.png"}, suffixes={"--png": (".png",)}) as plan:
        plan["--png"].write_bytes(b"x")
    assert (tmp_path / "o.png").read_bytes() == b"x"


def test_a_stop_whose_exit_was_dropped_still_writes_nothing(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # the whole bench (hostile28): "A signal 15 while run --png --rrd writes its temporary" ended 0 with both outputs
    # written, one run in three at a load of 25; SIGTERM's SystemExit is now noted, as SIGINT is, and checked here
    from seal_cli import fileio

    monkeypatch.setattr(fileio, "_STOPPED", [15])
    with pytest.raises(SystemExit) as ended, fileio.Outputs({"--png": tmp_path / "o.png"}) as plan:
        plan["--png"].write_bytes(b"x")
    assert ended.value.code == 143 and list(tmp_path.iterdir()) == []


def test_json_of_5000_digits_is_refused_at_the_number(tmp_path: Path) -> None:
    """Python's reader raised a bare ValueError (a traceback from bench parse --corpus and --constants, hostile29)."""
    with pytest.raises(SealError) as caught:
        json_value('{"a": [1,\n 2, -' + "9" * 5000 + "]}", "k.json", line=3)
    assert (caught.value.where.line, caught.value.where.column) == (4, 5)
    assert "an integer of 5,000 digits is more than seal reads" in caught.value.message
    path = tmp_path / "k.json"
    path.write_text('{"n": ' + "1" * 4301 + "}", encoding="utf-8")
    with pytest.raises(SealError, match=r"k\.json:1:7: an integer of 4,301 digits"):
        read_json(path)
    path.write_text('{"n": ' + "1" * 4300 + "}", encoding="utf-8")
    assert read_json(path)["n"] == int("1" * 4300)


def test_json_nested_too_deeply_is_refused_at_a_column(tmp_path: Path) -> None:
    path = tmp_path / "c.jsonl"
    path.write_text('{"ok": 1}\n{"s": "[[[", "a": ' + "[" * 100_000 + "]" * 100_000 + "}\n", encoding="utf-8")
    with pytest.raises(SealError) as caught:
        read_json_lines(path)
    where = caught.value.where
    assert (where.line, where.column) == (2, 19 + 498)  # the object is level 1; the string's brackets do not count
    assert "nested too deeply" in caught.value.message


def test_an_input_folders_files_are_inputs_too(tmp_path: Path) -> None:
    """A ROS 2 bag is a folder its reader reads file by file: an output onto one of its files, or a hard link to
    one, would replace it (hostile29); a new file in the folder is no input."""
    from seal_cli.fileio import Outputs

    bag = tmp_path / "x"
    bag.mkdir()
    (bag / "metadata.yaml").write_text("a: 1\n", encoding="utf-8")
    (tmp_path / "h.yaml").hardlink_to(bag / "metadata.yaml")
    for target in (bag / "metadata.yaml", tmp_path / "h.yaml"):
        with pytest.raises(SealError, match=r"would overwrite the input .*metadata\.yaml"):
            Outputs({"--output": target}, [bag])
    with Outputs({"--output": bag / "o.yaml"}, [bag]) as outputs:
        outputs["--output"].write_text("b: 2\n", encoding="utf-8")
    assert (bag / "o.yaml").read_text(encoding="utf-8") == "b: 2\n"
    assert (bag / "metadata.yaml").read_text(encoding="utf-8") == "a: 1\n"


@pytest.mark.parametrize(("text", "where", "key"), [
    ('{"text": "a", "text": "b"}', (3, 15), "text"),
    ('{"a": {"b": 1},\n "c": [{"d": 1}, {"d": 2, "e": {"x\\"{": 1, "x\\"{": 2}}]}', (4, 44), 'x"{'),
    ('[{"k": 1}, {"k": 1}, {"s": "{\\"k\\": 1, ", "k": 2, "k": 3}]', (3, 51), "k"),
])
def test_a_json_key_said_twice_in_one_object_is_refused_at_the_second(text: str, where: tuple[int, int],
                                                                       key: str) -> None:
    """Python's reader took the last silently (hostile30); keys in other objects, or inside strings, do not count."""
    with pytest.raises(SealError) as caught:
        json_value(text, "c.jsonl", line=3)
    assert (caught.value.where.line, caught.value.where.column) == where
    assert f"this object says the key {key!r} twice" in caught.value.message


def test_json_keys_said_once_in_each_object_are_read(tmp_path: Path) -> None:
    path = tmp_path / "k.json"
    path.write_text('{"a": {"b": 1}, "c": {"b": 2}, "d": [{"b": 3}, {"b": 4}]}', encoding="utf-8")
    assert read_json(path) == {"a": {"b": 1}, "c": {"b": 2}, "d": [{"b": 3}, {"b": 4}]}


@pytest.mark.skipif(not Path("/proc/self").is_dir(), reason="needs Linux's /proc")
def test_an_output_into_a_folder_that_takes_no_new_file_says_so_of_the_folder() -> None:
    """``/proc`` says "No such file or directory" even to root: it named a folder that exists (hostile30)."""
    from seal_cli import fileio

    with pytest.raises(SealError, match=r"cannot write --png /proc/o\.png: folder /proc does not take new files "
                                        r"\(No such file or directory"), fileio.Outputs({"--png": Path("/proc/o.png")}):
        pass


def test_a_read_only_folder_is_said_so(tmp_path: Path) -> None:
    import errno

    from seal_cli import fileio

    reason = fileio._reason(OSError(errno.EROFS, "Read-only file system"), tmp_path / "o.png", in_folder=True)
    assert reason.startswith(f"folder {tmp_path} does not take new files (Read-only file system")
    gone = fileio._reason(OSError(errno.ENOENT, "No such file or directory"), tmp_path / "d" / "o.png", in_folder=True)
    assert gone == f"folder {tmp_path / 'd'} does not exist"
