"""Shared paths for the package's tests: the repository, its scenes, ../shared/data."""

import os
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
SCENES = REPO / "bench" / "scenes"
SHARED = Path(os.environ.get("SHENLONG_SHARED_DATA", REPO.parent / "shared" / "data"))


def shared(relative: str) -> Path:
    """A file of ../shared/data, or a skip saying it is absent."""
    path = SHARED / relative
    if not path.exists():
        pytest.skip(f"{path} is absent (real scene data beside the repository)")
    return path


@pytest.fixture
def office_path() -> Path:
    return SCENES / "office_v3.json"
