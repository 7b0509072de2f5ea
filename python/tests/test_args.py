# python/tests/test_args.py - arguments of the wrong type or value are refused
# in Python's words (issue 30): TypeError for a model that is not text, a
# located ValueError for a NUL byte (C would stop reading there), and an
# option named as the argument (dt), not as the command line's --dt.
import pytest

import qdot

OSC = "coordinates x\nparameters m = 1, k = 1\nT = m/2*x'^2\nV = k/2*x^2\ninitial x = 1\n"


@pytest.mark.parametrize("bad", [None, 42, 1.5, ["coordinates x"]])
def test_model_of_wrong_type_is_type_error(bad):
    with pytest.raises(TypeError, match="str or bytes, not %s" % type(bad).__name__):
        qdot.Model(bad)


def test_model_file_of_wrong_type_is_type_error():
    with pytest.raises(TypeError, match="file is a str"):
        qdot.Model(OSC, file=None)


@pytest.mark.parametrize("text", [OSC[:20] + "\0" + OSC[20:], (OSC[:20] + "\0" + OSC[20:]).encode()])
def test_nul_byte_is_refused_where_it_is(text):
    # byte 20 is on line 2 ("parameters ..." starts at byte 14): column 7
    with pytest.raises(ValueError, match=r"^m\.qd:2:7: a NUL byte in the model text \(byte 20\)$"):
        qdot.Model(text, file="m.qd")


def test_nul_byte_after_a_whole_model_is_refused():
    # the text before the NUL parses: without the check the rest is lost silently
    with pytest.raises(ValueError, match=":6:1: a NUL byte"):
        qdot.Model(OSC + "\0V = 0\n")


def test_dt_zero_is_named_as_the_argument():
    m = qdot.Model(OSC)
    with pytest.raises(qdot.Error) as err:
        m.simulate(1, method="gl4", dt=0)
    msg = str(err.value)
    assert "the argument dt" in msg
    assert "--" not in msg
