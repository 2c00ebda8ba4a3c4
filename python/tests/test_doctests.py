"""The examples in the package's docstrings run as written."""

import doctest

import pytest

import casteljau


@pytest.mark.parametrize("module", ["casteljau", "casteljau.dask"])
def test_docstring_examples(module):
    if module == "casteljau.dask":
        pytest.importorskip("dask.array")
    mod = __import__(module, fromlist=["_"])
    failures, tried = doctest.testmod(mod, optionflags=doctest.NORMALIZE_WHITESPACE)
    assert tried > 0 and failures == 0
