"""scripts/plot_scale_decomposition.py on a run folder written here: it draws W, W_s and W_r of
W_final.csv, and a zonal W on a resting sphere (diagonal, as its stream matrix) is all W_s."""
import json
import sys

import numpy as np

import ddb


def test_draws_the_three_parts_of_the_final_state(tmp_path, monkeypatch, load_script):
    n = 6
    W = ddb.zeitlin_vorticity("zonal", n, 2) + 0.1 * ddb.zeitlin_vorticity("random", n, 3)
    with open(tmp_path / "W_final.csv", "w") as f:
        for row in W:
            f.write(",".join(repr(x) for x in np.concatenate([row.real, row.imag])) + "\n")
    summary = {"alpha": 0.5, "rotation": 0.0, "deformation_radius": None, "t_end": 1.0,
               "method": "ddb-cay"}
    (tmp_path / "summary.json").write_text(json.dumps(summary))
    script = load_script("plot_scale_decomposition")
    np.testing.assert_array_equal(script.read_matrix(tmp_path / "W_final.csv"), W)
    monkeypatch.setattr(sys, "argv", ["plot_scale_decomposition.py", str(tmp_path)])
    script.main()
    figure = tmp_path / "scale_decomposition.png"
    assert figure.stat().st_size > 10_000
    # The decomposition it draws: a zonal W is steady on a resting sphere, all W_s.
    zonal = ddb.zeitlin_vorticity("zonal", n, 2)
    steady, remainder = ddb.zeitlin(n, 0.5).scale_decomposition(zonal)
    np.testing.assert_allclose(steady, zonal, atol=1e-13)
    np.testing.assert_allclose(remainder, 0, atol=1e-13)
