"""Collects the `///` comments of the option structs of the application layer (src/app/*.hpp)
into one JSON file, so the Python docstrings say what the C++ says, once.

    option_help.py OUT.json HEADER...

Output: {"StructName": {"field": {"type": "C++ type", "help": "comment"}}}. A field's help is
the `///` block right above it, or its trailing `///<` comment; the type lets nested groups
(`InclineLaunchOptions launch;`) be followed from a command's struct to the field.
"""
import json
import re
import sys

STRUCT = re.compile(r"^\s*struct\s+(\w+)\s*(?::[^{]*)?\{\s*$")
# type name [= init | {init}] ; [///< comment]
FIELD = re.compile(r"^\s*([\w:<>, ]+?[\w>])\s+(\w+)\s*(?:=[^;]*|\{[^;]*\})?;\s*(?:///<?\s?(.*))?$")


def parse(text):
    structs = {}
    name, depth, pending = None, 0, []
    for line in text.splitlines():
        if name is None:
            m = STRUCT.match(line)
            if m:
                name, depth, pending = m.group(1), 1, []
                structs[name] = {}
            continue
        depth += line.count("{") - line.count("}")
        if depth <= 0:
            name = None
            continue
        stripped = line.strip()
        if depth != 1 and not (depth == 2 and stripped.endswith("{")):
            pending = []
            continue
        if stripped.startswith("///"):
            pending.append(stripped.lstrip("/").lstrip("<").strip())
            continue
        m = FIELD.match(line)
        if m and "(" not in line.split("///")[0]:
            ftype, field, trailing = m.group(1).strip(), m.group(2), m.group(3)
            text = " ".join(pending + ([trailing.strip()] if trailing else []))
            structs[name][field] = {"type": ftype, "help": text}
        pending = []
    return structs


def main(argv):
    out, headers = argv[1], argv[2:]
    structs = {}
    for h in sorted(headers):
        with open(h, encoding="utf-8") as f:
            structs.update(parse(f.read()))
    with open(out, "w", encoding="utf-8") as f:
        json.dump(structs, f, indent=1, sort_keys=True, ensure_ascii=False)
        f.write("\n")


if __name__ == "__main__":
    main(sys.argv)
