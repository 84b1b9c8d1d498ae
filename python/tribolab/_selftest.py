"""The binding mechanism on a command made to test it (python/tests/test_mechanism.py)."""
from . import _commands
from ._tribolab import _selftest as _ext

to_python = _ext.to_python
dump = _ext.dump
_commands.export(_ext, globals())
