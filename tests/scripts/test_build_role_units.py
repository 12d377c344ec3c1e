"""``scripts/build_lexical_units.py --propbank``: lexical units from the thematic roles of a verb's main
PropBank sense, on a tiny PropBank of its own, and the shipped ``framelib/role_units.yaml``."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest
import yaml

from tests.conftest import run_script

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "scripts" / "build_lexical_units.py"


def roleset(ident: str, framenet: str = "", **classes: str) -> str:
    """A PropBank roleset: ``classes`` maps a VerbNet class to its roles for ARG0, ARG1, ARG2."""
    links = f'<lexlink class="{framenet}" resource="FrameNet"/>' if framenet else ""
    roles = ""
    for n in range(3):
        rolelinks = "".join(f'<rolelink class="{vn}" resource="VerbNet">{r.split()[n]}</rolelink>'
                            for vn, r in classes.items() if len(r.split()) > n)
        roles += f'<role n="{n}" f="PAG" descr="arg{n}"><rolelinks>{rolelinks}</rolelinks></role>'
    lemma = ident.rsplit(".", 1)[0]
    return (f'<roleset id="{ident}" name="x"><aliases><alias pos="v">{lemma}</alias></aliases>'
            f'<roles>{roles}</roles><lexlinks>{links}</lexlinks></roleset>')


def frameset(*rolesets: str) -> str:
    return f'<?xml version="1.0"?><frameset><predicate lemma="x">{"".join(rolesets)}</predicate></frameset>'


VN = {  # VerbNet class names hold dashes, which a keyword argument cannot: short names, replaced in the files
    "give": "give-13.1", "tell": "transfer_mesg-37.1.1", "fulfil": "fulfilling-13.4.1", "say": "say-37.7-1",
    "confess": "confess-37.10", "appear": "reflexive_appearance-48.1.2", "sound": "animal_sounds-38",
    "cut": "cut-21.1-1", "put": "put-9.1", "spatial": "put_spatial-9.2-1", "fill": "fill-9.8",
}


def tiny_propbank(folder: Path) -> Path:
    files = {
        "give": roleset("give.01", "Giving", give="agent theme recipient"),
        "tell": roleset("tell.01", "Telling", tell="agent topic recipient"),
        "proffer": roleset("proffer.01", "", fulfil="agent theme recipient"),            # Give by its roles
        "blurt": roleset("blurt.01", "", say="agent topic recipient", confess="agent topic recipient",
                         appear="agent theme recipient"),                                   # Tell, 2 votes to 1
        "proclaim": roleset("proclaim.01", "", say="agent topic recipient", fulfil="agent theme recipient"),
        "bleat": roleset("bleat.01", "", sound="agent theme recipient"),   # Give's roles, another Levin class
        "snip": roleset("snip.01", "", cut="agent patient"),               # no recipient: stands for nothing
        "cable": roleset("cable.01", "", tell="agent topic recipient"),    # Tell's roles, but mostly a noun
        "put": roleset("put.01", "Placing", put="agent theme destination"),
        "drape": roleset("drape.01", "Placing", spatial="agent theme destination"),   # Place by where it goes
        "prop": roleset("prop.01", "", spatial="agent theme destination"),   # where, but FrameNet says no Placing
        "stuff": roleset("stuff.01", "Placing", fill="agent destination theme"),   # its object is where: no Place
    }
    for name, text in files.items():
        for short, vn in VN.items():
            text = text.replace(f'class="{short}"', f'class="{vn}"')
        (folder / f"{name}.xml").write_text(frameset(text))
    (folder / "broken.xml").write_text("<frameset><predicate></frameset>")
    return folder


VERBS = ["proffer", "blurt", "proclaim", "bleat", "snip", "cable", "give", "tell", "put", "drape", "prop", "stuff"]


def tiny_wordnet(folder: Path) -> Path:
    """A WordNet of one synset per verb, each used as a verb three times; "cable" nine times as a noun."""
    folder.mkdir()
    data, index = ["  1 licence line"], ["  1 licence line"]
    for n, verb in enumerate(VERBS):
        offset = f"{2000000 + n:08d}"
        data.append(f"{offset} 32 v 01 {verb} 0 000 | to {verb}")
        index.append(f"{verb} v 1 0 1 1 {offset}")
    (folder / "data.verb").write_text("\n".join(data) + "\n")
    (folder / "index.verb").write_text("\n".join(sorted(index)) + "\n")
    (folder / "index.noun").write_text("  1 licence line\ncable n 2 0 2 2 03000001 03000002\n")
    uses = [f"{verb}%2:32:00:: 1 3" for verb in VERBS] + ["cable%1:06:00:: 1 9"]   # cable: a wire, mostly
    (folder / "cntlist.rev").write_text("\n".join(uses) + "\n")
    return folder


def run(*args: str) -> subprocess.CompletedProcess[str]:
    return run_script(SCRIPT, *args)


def test_a_verb_takes_the_frame_whose_verbs_have_its_roles(tmp_path: Path) -> None:
    out, frames = tmp_path / "units.yaml", tiny_propbank(tmp_path)
    wordnet = str(tiny_wordnet(tmp_path / "wordnet"))
    done = run("--propbank", str(frames), "--wordnet", wordnet, "--out", str(out))
    assert done.returncode == 0, done.stderr
    assert "broken.xml:1:" in done.stderr and "skipped" in done.stderr
    units = {e["unit"]: e for e in yaml.safe_load(out.read_text())["lexical_units"]}
    # proclaim: a vote each (a tie); bleat: Give's roles in a class of sounds; snip: nobody receives;
    # cable: mostly a noun; prop: a destination, but no FrameNet Placing; stuff: its object is the destination
    assert sorted(units) == ["blurt", "drape", "proffer"]
    assert (units["proffer"]["frame"], units["blurt"]["frame"], units["drape"]["frame"]) == ("Give", "Tell", "Place")
    assert units["drape"]["source"] == ("propbank:drape.01 -> VerbNet put_spatial-9.2-1 "
                                        "(agent, destination, theme: as put.01, FrameNet Placing)")
    assert units["proffer"]["source"] == ("propbank:proffer.01 -> VerbNet fulfilling-13.4.1 "
                                          "(agent, recipient, theme: as give.01)")
    assert run("--propbank", str(frames), "--wordnet", wordnet, "--out", str(out), "--check").returncode == 0
    alone = run("--propbank", str(frames), "--out", str(out))
    assert alone.returncode == 1 and "--propbank needs --wordnet" in alone.stderr


def test_a_folder_without_frame_files_is_named(tmp_path: Path) -> None:
    done = run("--propbank", str(tmp_path), "--out", str(tmp_path / "out.yaml"))
    assert done.returncode == 1 and "no PropBank frame files" in done.stderr and "Traceback" not in done.stderr


def test_the_shipped_file_is_what_propbank_gives() -> None:
    checkout = os.environ.get("PROPBANK_FRAMES")          # a propbank-frames checkout @ c66e0cc
    if not checkout or not Path(checkout, "frames").is_dir():
        pytest.skip("no propbank-frames checkout (set PROPBANK_FRAMES)")
    if not Path("/usr/share/wordnet/index.noun").is_file():
        pytest.skip("WordNet 3.0 is not installed (apt-get install wordnet-base)")
    done = run("--propbank", checkout, "--wordnet", "/usr/share/wordnet", "--check")
    assert done.returncode == 0, done.stderr
