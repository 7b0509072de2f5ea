# python/tests/test_docs.py - docs/python.md's `>>>` examples are run as
# doctests from the repository's root (the manual's examples are tests).
import doctest
import os
import re

from conftest import ROOT


def test_python_md_examples(monkeypatch):
    monkeypatch.chdir(ROOT)
    with open(os.path.join(ROOT, "docs", "python.md")) as fh:
        # a closing fence ends an example's expected output, as a blank line does
        text = re.sub(r"(?m)^```.*$", "", fh.read())
    test = doctest.DocTestParser().get_doctest(text, {}, "python.md", "docs/python.md", 0)
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    runner.run(test)
    result = runner.summarize(verbose=False)
    assert result.attempted > 15
    assert result.failed == 0
