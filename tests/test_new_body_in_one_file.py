"""A new lower body is one file: the body below is declared here only (registered by its
decorator, no other edit) and then runs through collide with the FE solids, the command line
(its --lower choice and its own option), a study's keys and a collide --from round trip.

The body is a wall block of its own size (width and depth by a), a wall of another outer
shape. At the size the FE solids give the built-in wall (40 a) it is that wall: same mesh,
same forms, so its collision equals the wall's bit for bit; a smaller block, clamped nearer
the contact, is stiffer."""

import csv
import json
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
import pytest

from ehdfem import CollisionParameters, RunConfig, collide, elasticity, film_radii
from ehdfem.checks import InputError
from ehdfem.cli.main import main, parsers
from ehdfem.outputs import registry
from ehdfem.settings import setting
from ehdfem.solids.fe.bodies import LowerBody, register
from ehdfem.study.sweep import Study, run_study
from meshes import contact

pytestmark = pytest.mark.serial


@register
@dataclass(frozen=True)
class Block(LowerBody):
    """A wall block [0, L] x [-L, 0] (by a) of the wall's material, clamped at its base."""

    kind: ClassVar[str] = "block"
    description: ClassVar[str] = "wall block of its own size"
    clamped: ClassVar[tuple[int, ...]] = (contact.LOWER_BOTTOM,)
    block_size: float = setting(
        40.0, help="width and depth L of the block", unit="by a", lower=2.0, upper=100.0
    )

    def materials(self, wall):
        return {contact.LOWER: wall}

    def geometry(self, gap, contact_radii, size):
        return contact.build, (gap, contact_radii, "wall", self.block_size, 1.0, 1.0, None)


PARAMS = CollisionParameters.from_settings(St=10.0, eps=1e-3, delta=1e-3, p_cav=-2.0)
SMALL = ["--St", "10", "--eps", "1e-3", "--delta", "1e-3", "--p-cav=-2", "--nodes", "40"]


def outputs(summary: dict) -> dict:
    """The collision's raw outputs (registry.computed's names) from a summary."""
    return {name: summary[name] for name in registry.names() if name in summary}


@pytest.mark.slow
def test_the_block_collides_as_the_wall_it_equals():
    """At 40 a the block is the built-in wall: every output of the FE collision (40 film
    nodes) is bit-equal; the run settings name the block and its size."""
    block = collide(PARAMS, RunConfig.from_settings(model="fem", lower="block", nodes=40))
    wall = collide(PARAMS, RunConfig.from_settings(model="fem", nodes=40))
    assert outputs(block.summary()) == outputs(wall.summary())
    run = block.summary()["inputs"]["run"]
    assert (run["lower"], run["block_size"]) == ("block", 40.0)


@pytest.mark.slow
def test_a_smaller_block_is_stiffer():
    """A block of 6 a, clamped 6 a below the contact instead of 40 a, opens the gap less
    under the same Hertz-like film pressure (the central deflection, by x0), and the setting
    reaches the solids."""
    radii = film_radii(PARAMS, 40)
    pressure = np.sqrt(np.clip(1 - (radii / 0.8) ** 2, 0, None))
    deflections = []
    for size in (40.0, 6.0):
        config = RunConfig.from_settings(model="fem", lower="block", block_size=size, nodes=40)
        compliance = elasticity(PARAMS, radii, config)
        deflections.append(compliance.deflection(pressure)[0])
        compliance.close()
    assert 0 < deflections[1] < deflections[0]


@pytest.mark.slow
def test_the_block_on_the_command_line_and_again_from_its_json(tmp_path, capsys):
    """--lower block --block-size: the JSON records them, and collide --from it runs the same
    collision again, bit for bit."""
    first, again = tmp_path / "first.json", tmp_path / "again.json"
    argv = ["collide", *SMALL, "--model", "fem", "--lower", "block", "--block-size", "30"]
    assert main([*argv, "--json", str(first)]) == 0
    recorded = json.loads(first.read_text())
    assert recorded["inputs"]["run"]["lower"] == "block"
    assert recorded["inputs"]["run"]["block_size"] == 30.0
    assert main(["collide", "--from", str(first), "--json", str(again)]) == 0
    a, b = (json.loads(p.read_text()) for p in (first, again))
    a.pop("provenance"), b.pop("provenance")
    assert a == b
    capsys.readouterr()


def test_the_block_is_a_choice_and_an_option_of_collide(capsys):
    """--lower offers the block with its description; --block-size shows its help, unit, range
    and default; a value out of range is refused naming the option and the range."""
    _, commands = parsers()
    helps = {a.option_strings[0]: a for a in commands["collide"]._actions if a.option_strings}
    assert "block" in helps["--lower"].choices
    assert "block (wall block of its own size)" in helps["--lower"].help
    assert helps["--block-size"].help == (
        "width and depth L of the block [by a], [2, 100]; default: 40"
    )
    assert main(["collide", *SMALL, "--model", "fem", "--lower", "block", "--block-size", "1"])
    err = capsys.readouterr().err
    assert err.startswith("ehdfem collide: error: --block-size: ") and "[2, 100]" in err
    assert main(["collide", *SMALL, "--model", "fem", "--block-size", "10"]) == 2
    assert "--block-size: needs lower = 'block', not 'wall'" in capsys.readouterr().err


def test_the_block_is_a_study_key(tmp_path):
    """[grid] over block_size with [run] lower = "block": one configuration per point; the
    size without the block is refused naming both."""
    study_file = tmp_path / "s.toml"
    study_file.write_text(
        "[grid]\nSt = [10.0]\neps = [1e-3]\ndelta = [1e-3]\nblock_size = [10.0, 40.0]\n"
        '[run]\nmodel = "fem"\nlower = "block"\n'
    )
    study = Study(study_file)
    assert [study.config(p).lower for p in study.points] == [Block(10.0), Block(40.0)]
    bad = tmp_path / "b.toml"
    bad.write_text("[grid]\nSt = [10.0]\neps = [1e-3]\nblock_size = [10.0]\n")
    with pytest.raises(InputError, match="block_size needs lower = 'block'"):
        Study(bad)


@pytest.mark.slow
def test_a_study_sweeps_the_block(tmp_path):
    """A study over two block sizes (40 film nodes) runs; its rows and table carry the
    block's kind and size, and the 40 a point's e_n is the wall's, bit for bit."""
    study_file = tmp_path / "s.toml"
    study_file.write_text(
        "[grid]\nSt = [10.0]\neps = [1e-3]\ndelta = [1e-3]\np_cav = [-2.0]\n"
        'block_size = [6.0, 40.0]\n[run]\nmodel = "fem"\nlower = "block"\n'
        "[numerics]\nnodes = 40\n"
    )
    rows = run_study(Study(study_file), None, progress=None)
    assert [(row["lower"], row["block_size"]) for row in rows] == [("block", 6.0), ("block", 40.0)]
    wall = collide(PARAMS, RunConfig.from_settings(model="fem", nodes=40))
    assert rows[1]["e_n"] == wall.normal.e_n
    with open(Study(study_file).table) as table:
        assert {"lower", "block_size"} <= set(next(csv.DictReader(table)))
