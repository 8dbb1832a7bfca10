"""batch(): serial, and on a Dask LocalCluster, equal to each other and to the scenes'."""

import pytest

import stressfield as sf
from conftest import SCENES

TASKS = [
    SCENES / "sphere_ball_on_flat.toml",
    str(SCENES / "line_tau1.toml"),
    (SCENES / "gear_pitch_point.toml").read_text(),
    SCENES / "rough_worn_on_flat.toml",
]


def test_batch_serial_is_each_scene_s():
    results = sf.batch(TASKS)
    assert len(results) == 4
    assert results[0] == sf.load_scene(TASKS[0]).hertz()
    assert results[3] == sf.load_scene(TASKS[3]).contact().to_dict()
    assert results[2]["kind"] == "line" and results[2]["scene"] == "scene"


def test_batch_on_a_local_cluster_is_the_serial_run():
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    ) as cluster, distributed.Client(cluster) as client:
        on_cluster = sf.batch(TASKS, client=client)
        with pytest.raises(sf.StressfieldError, match="cannot read the scene"):
            sf.batch([SCENES / "missing.toml"], client=client)
    assert on_cluster == sf.batch(TASKS)
