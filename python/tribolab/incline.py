"""The disc on a rough incline (incline study): the `tribolab incline` commands.

Each function takes the command line's options as keywords (snake_case, the same defaults)
and returns the command's --json object as a dict, with numpy arrays beside it.
"""
from . import _commands
from ._tribolab import incline as _ext

_commands.export(_ext, globals())
