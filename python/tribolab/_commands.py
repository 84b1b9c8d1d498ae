"""Builds the Python functions of one area from the specs the extension registers (the C++
mechanism is python/src/bind.hpp): the signature (keywords named as the command line's
options in snake_case, defaults from the C++ option structs) and the docstring (each option's
help from the `///` comment on its field, collected at build time into _option_help.json).
"""
import functools
import inspect
import json
import os

_HELP_FILE = os.path.join(os.path.dirname(__file__), "_option_help.json")


@functools.lru_cache(maxsize=None)
def _structs():
    try:
        with open(_HELP_FILE, encoding="utf-8") as f:
            return json.load(f)
    except OSError:
        return {}


def option_help(struct, path):
    """The `///` comment of field `path` ("launch.mu") of C++ struct `struct`, following
    nested groups by their field types; "" when unknown."""
    structs = _structs()
    parts = path.split(".")
    for i, field in enumerate(parts):
        entry = structs.get(struct, {}).get(field)
        if entry is None:
            return ""
        if i + 1 == len(parts):
            return entry["help"]
        struct = entry["type"].split("::")[-1]
    return ""


def _doc(spec):
    lines = [spec["summary"], "", "Parameters", "----------"]
    for o in spec["options"]:
        default = "" if o["positional"] else ", default " + repr(o["default"])
        lines.append(f"{o['keyword']} : {o['type']}{default}")
        if "help" in o:  # a declared field (src/app/common/option_fields.hpp)
            text = o["help"] + (", " + o["unit"] if o["unit"] else "")
        else:
            text = option_help(spec["options_struct"], o["path"])
        if text:
            lines.append("    " + text)
    lines += ["", "Returns", "-------",
              "dict",
              "    The keys and numbers of `tribolab ... --json` (docs/cli.md), and beside them:",
              "    " + (spec["returns"] or "no arrays"),
              "", "Raises", "------",
              "ValueError",
              "    Bad input, with the command line's message (naming the option as its keyword).",
              "TypeError",
              "    An unknown keyword or a value of the wrong type."]
    return "\n".join(lines)


def _function(module_name, spec, ext_function):
    params = []
    for o in spec["options"]:
        if o["positional"]:
            params.append(inspect.Parameter(o["keyword"], inspect.Parameter.POSITIONAL_OR_KEYWORD))
    for o in spec["options"]:
        if not o["positional"]:
            params.append(inspect.Parameter(o["keyword"], inspect.Parameter.KEYWORD_ONLY,
                                            default=o["default"]))
    signature = inspect.Signature(params)

    def command(*args, **kwargs):
        bound = signature.bind(*args, **kwargs)  # TypeError: unknown keyword, missing argument
        return ext_function(**bound.arguments)

    command.__name__ = command.__qualname__ = spec["name"]
    command.__module__ = module_name
    command.__signature__ = signature
    command.__doc__ = _doc(spec)
    return command


def export(ext_module, namespace):
    """Defines in `namespace` (a module's globals()) one function per spec of `ext_module`."""
    names = []
    for spec in getattr(ext_module, "_specs", []):
        namespace[spec["name"]] = _function(namespace["__name__"], spec,
                                            getattr(ext_module, "_" + spec["name"]))
        names.append(spec["name"])
    namespace["__all__"] = names
    return names
