# python/tests/conftest.py - the package under test is python/qdot of this
# source tree, loading the libqdot.so of the build named by QDOT_BUILD (ctest
# passes it; QDOT_LIB, when set, wins as it does for users).
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "python"))
if "QDOT_LIB" not in os.environ and os.environ.get("QDOT_BUILD"):
    os.environ["QDOT_LIB"] = os.environ["QDOT_BUILD"]

EXAMPLES = os.path.join(ROOT, "examples")
