"""`python -m shenlong.ray_bench`: shards as Ray tasks on a local Ray, merged into the same
figures as one run; a shard that fails twice is named, never dropped."""

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

import shenlong
from conftest import REPO

ray = pytest.importorskip("ray")

SUITE = REPO / "bench" / "holdout2" / "holdout2.suite.json"
ENV = {**os.environ, "RAY_AUTH_MODE": "disabled", "RAY_USAGE_STATS_ENABLED": "0"}


def figures(report):
    """What must agree between runs: counts and rates, not timings."""
    out = {}
    for name, system in report["systems"].items():
        out[name] = {
            "overall": (system["overall"]["n"], system["overall"]["success_rate"]),
            "categories": {c: (f["n"], f["success_rate"]) for c, f in system["categories"].items()},
            "queries": system["queries"],
        }
    return out, sorted(f["instance"] for f in report["failures"])


def test_two_shards_on_ray_merge_to_the_single_machine_report(tmp_path):
    single = shenlong.bench(SUITE, tmp_path / "single", collide=True)
    run = subprocess.run(
        [sys.executable, "-m", "shenlong.ray_bench", str(SUITE), "--shards", "2",
         "--out", str(tmp_path / "ray"), "--collide", "--num-cpus", "2"],
        capture_output=True, text=True, env=ENV, timeout=600,
    )
    assert run.returncode == 0, run.stderr
    assert "shards done 2/2" in run.stderr
    merged = json.loads((tmp_path / "ray" / "report.json").read_text())
    assert figures(merged) == figures(single)
    assert "missing_shards" not in merged
    for k in (1, 2):
        info = json.loads((tmp_path / "ray" / "shards" / f"shard-{k}" / "run.json").read_text())
        assert info["shard"] == [k, 2]


def flaky_shard(suite, shard, options, prior):
    """Shard 2 fails every time; shard 1 fails on its first attempt only (a marker file)."""
    from shenlong.ray_bench import run_shard

    marker = Path(options.pop("marker"))
    if shard[0] == 2:
        raise RuntimeError("the node ran out of disk")
    if shard[0] == 1 and not marker.exists():
        marker.write_text("tried")
        raise RuntimeError("a passing hiccup")
    return run_shard(suite, shard, options, prior)


def test_a_shard_that_fails_twice_is_named_and_the_rest_is_merged(tmp_path, capsys):
    from shenlong import ray_bench

    # The workers import this module to run flaky_shard.
    here = str(Path(__file__).parent)
    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False,
             runtime_env={"env_vars": {"PYTHONPATH": os.pathsep.join([here, os.environ.get("PYTHONPATH", "")])}})
    try:
        options = {"llm": "offline", "system": "cga", "collide": False, "limit": None,
                   "jobs": 1, "marker": str(tmp_path / "marker")}
        status = ray_bench._run(ray, str(SUITE), 2, options, tmp_path / "out", shard_fn=flaky_shard)
    finally:
        ray.shutdown()
    assert status == 1
    err = capsys.readouterr().err
    assert "shard 2/2 failed twice: " in err and "out of disk" in err
    assert (tmp_path / "marker").exists()  # shard 1 failed once and was retried
    report = json.loads((tmp_path / "out" / "report.json").read_text())
    assert report["missing_shards"] == ["2/2"]
    assert 0 < report["systems"]["cga"]["overall"]["n"] < 288
    assert "Partial" in (tmp_path / "out" / "report.md").read_text()


def test_bad_arguments_fail_with_one_line(tmp_path):
    run = subprocess.run(
        [sys.executable, "-m", "shenlong.ray_bench", str(tmp_path / "none.suite.json"),
         "--shards", "2", "--out", str(tmp_path / "o")],
        capture_output=True, text=True, env=ENV,
    )
    assert run.returncode == 2 and "no such suite file" in run.stderr
    run = subprocess.run(
        [sys.executable, "-m", "shenlong.ray_bench", str(SUITE), "--shards", "0", "--out", "o"],
        capture_output=True, text=True, env=ENV,
    )
    assert run.returncode == 2 and "--shards must be at least 1" in run.stderr


def test_an_output_that_is_a_file_is_refused_before_any_shard_runs(tmp_path):
    import subprocess
    import sys

    out = tmp_path / "results.txt"
    out.write_text("precious")
    suite = Path(__file__).resolve().parents[2] / "bench" / "natural.suite.json"
    r = subprocess.run(
        [sys.executable, "-m", "shenlong.ray_bench", str(suite), "--shards", "2", "--out", str(out)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert r.returncode == 2, r.stderr
    assert len(r.stderr.strip().splitlines()) == 1, r.stderr
    assert "not a folder" in r.stderr
    assert out.read_text() == "precious"
