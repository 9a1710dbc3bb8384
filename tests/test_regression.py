"""Refactoring guard: the outputs of 23 collisions equal the stored table to 1e-10 relative.

The outputs are those of a sweep table row (ehdfem.study.OUTPUTS): rebound and status, e_n,
the largest rebound velocity, the thinnest film, the largest force, the contact time, the
largest compression, e_t, the spin change, the energy error and the film nodes used.

The table (tests/data/regression.json) was computed with the code before the parts of the
collision problem were separated (film, cavitation models, time stepper, elasticity), and
every later restructuring must reproduce it: it checks that code moved without changing its
arithmetic. It is not a physics check (those compare with exact results elsewhere); when a
physics change moves these numbers on purpose, regenerate the table with
tests/regression_cases.py and say why in the commit.
"""

import json
from pathlib import Path

import pytest
from regression_cases import OUTPUTS, cases, run

STORED = json.loads((Path(__file__).parent / "data" / "regression.json").read_text())


@pytest.mark.serial
@pytest.mark.parametrize("name,inputs,keywords", cases(), ids=[c[0] for c in cases()])
def test_outputs_equal_the_stored_table(name, inputs, keywords):
    computed, stored = run(inputs, keywords), STORED[name]
    for output in OUTPUTS:
        if not isinstance(stored[output], float):
            assert computed[output] == stored[output], output
        else:
            assert computed[output] == pytest.approx(stored[output], rel=1e-10, abs=1e-300), output
