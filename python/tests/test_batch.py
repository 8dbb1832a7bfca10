"""batch(): serial, and on a Dask LocalCluster, equal to each other and to the scenes'."""

import pytest

import stressfield as sf
from conftest import SCENES

# A scene whose load is out of range: its own error.
BAD = (SCENES / "sphere_ball_on_flat.toml").read_text().replace('load = "300 N"', 'load = "1e20 N"')

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
        # One bad task among good ones: the others' results are kept (issue 50).
        mixed = sf.batch([TASKS[0], BAD, TASKS[1]], client=client, errors="return")
    assert on_cluster == sf.batch(TASKS)
    assert mixed[0] == on_cluster[0] and mixed[2] == on_cluster[1]
    assert isinstance(mixed[1], sf.StressfieldError) and "tasks[1]" in str(mixed[1])


def test_one_bad_task_is_named_by_its_index_and_keeps_the_others():
    """Issue 50: a failing task lost the good results and was named `./scene.toml`."""
    assert 'load = "1e20 N"' in BAD
    tasks = [TASKS[0], BAD, TASKS[1], BAD]
    with pytest.raises(sf.BatchError) as caught:
        sf.batch(tasks)
    error = caught.value
    assert isinstance(error, sf.StressfieldError)
    message = str(error)
    assert message.startswith("batch: tasks[1] of 4 (TOML text): "), message
    assert "contact.load" in message and "1 more task(s) failed: tasks[3]" in message
    assert "hint:" in message and ".results" in message
    assert error.results[0] == sf.load_scene(TASKS[0]).hertz()
    assert error.results[2] == sf.load_scene(TASKS[1]).hertz()
    assert error.results[1] is None and error.results[3] is None
    assert sorted(error.errors) == [1, 3]
    returned = sf.batch(tasks, errors="return")
    assert returned[0] == error.results[0] and returned[2] == error.results[2]
    assert str(returned[1]) == str(error.errors[1])
    with pytest.raises(sf.StressfieldError, match='errors must be "raise" or "return"'):
        sf.batch(tasks, errors="ignore")
