"""Closed-form restitution models: conventions and fits that recover known coefficients."""

import numpy as np
import pytest

from ehdfem import closedform as cf

pytestmark = pytest.mark.serial


def test_formulas_and_stokes_conventions():
    assert cf.davis_rager_good([5.0, 20.0], 10.0, 0.9).tolist() == [0.0, pytest.approx(0.45)]
    # Legendre's St includes added mass: St_L = St (1 + rho_f/(2 rho_p))
    assert cf.legendre(35.0) == pytest.approx(np.exp(-1))
    assert cf.legendre(35.0 / 1.5, density_ratio=1.0) == pytest.approx(np.exp(-1))
    # Yade's St = rho V D / mu = 9 St
    assert cf.yade(1.0, 0.5 * np.exp(-9.0), e_dry=0.8) == pytest.approx(1e-3)
    assert cf.yade(2.0, 0.5 * np.exp(-9.0), e_dry=0.8) == pytest.approx(0.4)


def test_fit_normal_recovers_e_inf_and_critical_stokes():
    St = np.geomspace(2, 500, 30)
    e_n = cf.davis_rager_good(St, 7.5, 0.93)
    e_inf, St_c = cf.fit_normal(St, e_n)
    assert e_inf == pytest.approx(0.93, rel=1e-12) and St_c == pytest.approx(7.5, rel=1e-12)


def test_fit_table_recovers_synthetic_laws():
    """Rows made from known laws: St_c = 3.2 eps^-0.13, e_inf = 0.95, 1 - e_t = delta 0.8
    St^-0.6 eps^0.1, spin = delta 2 St^-0.6 eps^0.1. The fits return them to 1e-10."""
    rows = []
    for eps in (1e-5, 1e-4, 1e-3, 1e-2):
        St_c = 3.2 * eps**-0.13
        for St in np.geomspace(3, 1000, 20):
            e_n = float(cf.davis_rager_good(St, St_c, 0.95))
            loss = 0.01 * 0.8 * St**-0.6 * eps**0.1
            rows.append(
                {
                    "status": "ok:rebound",
                    "eps": eps,
                    "delta": 0.01,
                    "layer": "thin",
                    "p_cav": -5,
                    "St": St,
                    "e_n": e_n,
                    "e_t": 1 - loss,
                    "spin_change": 2.5 * loss,
                }
            )
    fit = cf.fit_table(rows)
    assert all(
        g["St_c"] == pytest.approx(3.2 * g["eps"] ** -0.13, rel=1e-10) for g in fit["normal"]
    )
    assert all(g["e_inf"] == pytest.approx(0.95, rel=1e-10) for g in fit["normal"])
    law = fit["critical_stokes_law"]
    assert law["coefficient"] == pytest.approx(3.2, rel=1e-10) and law["eps"] == pytest.approx(
        -0.13, rel=1e-10
    )
    t = fit["tangential_loss"]
    assert (t["coefficient"], t["St"], t["eps"]) == pytest.approx((0.8, -0.6, 0.1), rel=1e-8)
    assert fit["spin_change"]["coefficient"] == pytest.approx(2.0, rel=1e-8)
    assert t["max_error"] < 1e-12


def test_fit_table_keeps_film_models_apart():
    """A table with two cavitation models (St_c = 3 eps^-0.1 and 5 eps^-0.2): each model gets
    its own e_n fits and St_c law, recovered to 1e-10, instead of one fit over both."""
    laws = {"truncate": (3.0, -0.1), "mass-conserving": (5.0, -0.2)}
    rows = [
        {
            "status": "ok:rebound",
            "eps": eps,
            "delta": 0.01,
            "cavitation": model,
            "St": St,
            "e_n": float(cf.davis_rager_good(St, a * eps**b, 0.9)),
        }
        for model, (a, b) in laws.items()
        for eps in (1e-5, 1e-3)
        for St in np.geomspace(10, 1000, 12)
    ]
    fit = cf.fit_table(rows)
    assert len(fit["normal"]) == 4 and "critical_stokes_law" not in fit
    found = {law["model"]["cavitation"]: law for law in fit["critical_stokes_laws"]}
    for model, (a, b) in laws.items():
        assert (found[model]["coefficient"], found[model]["eps"]) == pytest.approx(
            (a, b), rel=1e-10
        )
