#!/usr/bin/env python3
"""Generates the bindings of libdbs from include/dbs.h, which is written for it: one prototype
per line, plain C types, every constant a `#define DBS_NAME <number>`, callbacks as
`typedef ... (*dbs_name_fn)(...)`. Each OUTPUT's extension says which:
  .py   the ctypes declarations of the Python package (python/libdbs/_capi.py);
  .inc  the Fortran constants and interface blocks (fortran/dbs_capi.inc; fortran_bindings.py).

usage: generate_bindings.py DBS_H OUTPUT...            writes each OUTPUT
       generate_bindings.py --check DBS_H OUTPUT...    exit 1 when an OUTPUT differs from what it would write
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fortran_bindings  # noqa: E402  (beside this script)

# C parameter and return types -> ctypes expressions. Handles (pointers to the opaque
# structs) travel as void pointers; out-handles as pointers to them.
SCALARS = {
    "int": "ctypes.c_int",
    "int32_t": "ctypes.c_int32",
    "size_t": "ctypes.c_size_t",
    "double": "ctypes.c_double",
    "void *": "ctypes.c_void_p",
    "const char *": "ctypes.c_char_p",
    "double *": "ctypes.POINTER(ctypes.c_double)",
    "const double *": "ctypes.POINTER(ctypes.c_double)",
    "int32_t *": "ctypes.POINTER(ctypes.c_int32)",
    "const int32_t *": "ctypes.POINTER(ctypes.c_int32)",
    "size_t *": "ctypes.POINTER(ctypes.c_size_t)",
    "const size_t *": "ctypes.POINTER(ctypes.c_size_t)",
}


def ctype_of(c_type, callbacks):
    c_type = re.sub(r"\s+", " ", c_type.strip()).replace(" *", " *")
    if c_type in SCALARS:
        return SCALARS[c_type]
    if c_type in callbacks:
        return callbacks[c_type][0]
    if re.fullmatch(r"(const )?dbs_\w+ \*", c_type):
        return "ctypes.c_void_p"
    if re.fullmatch(r"(const )?dbs_\w+ \*\*", c_type):
        return "ctypes.POINTER(ctypes.c_void_p)"
    raise SystemExit(f"generate_bindings: no ctypes type for C type '{c_type}'")


def read_header(text):
    constants = re.findall(r"^#define\s+DBS_(\w+)\s+(-?[0-9][0-9.eE+-]*)\b", text, re.MULTILINE)
    # an option's type opens the comment beside it: "/* int; ..." or "/* double; ..."
    integer_options = re.findall(r"^#define\s+DBS_(OPT_\w+)\s+[0-9]+\s+/\*\s*int;", text, re.MULTILINE)
    callbacks = {}
    for ret, name, params in re.findall(r"^typedef\s+(.*?)\(\*\s*(dbs_\w+_fn)\)\((.*)\);", text, re.MULTILINE):
        python_name = name[len("dbs_"):].upper()
        restype = "None" if ret.strip() == "void" else ctype_of(ret, {})
        argtypes = [ctype_of(fortran_bindings.split_parameter(p)[0], {}) for p in params.split(",")]
        callbacks[name] = (python_name, restype, argtypes)
    functions = []
    for line in text.splitlines():
        match = re.match(r"\s*DBS_API\s+(.*?)\b(dbs_\w+)\s*\((.*)\)\s*;", line)
        if not match:
            continue
        ret, name, params = match.groups()
        restype = "None" if ret.strip() == "void" else ctype_of(ret, callbacks)
        params = params.strip()
        argtypes = [] if params in ("", "void") else [ctype_of(fortran_bindings.split_parameter(p)[0], callbacks) for p in params.split(",")]
        names = [] if params in ("", "void") else [fortran_bindings.split_parameter(p)[1] for p in params.split(",")]
        functions.append((name, restype, argtypes, names))
    return constants, integer_options, callbacks, functions


def render(constants, integer_options, callbacks, functions):
    out = ['"""The C API of libdbs as ctypes declarations: every constant and function of dbs.h.',
           "",
           "Generated from include/dbs.h by scripts/generate_bindings.py: do not edit (a test",
           'compares this file with what the script writes)."""',
           "import ctypes",
           "",
           "# ---- constants (the DBS_ prefix dropped) ----"]
    out += [f"{name} = {value}" for name, value in constants]
    out += ["", "# the options whose values are integers (\"int;\" beside them in dbs.h)",
            f"INTEGER_OPTIONS = ({', '.join(integer_options)},)"]
    out += ["", "# ---- callback types ----"]
    for python_name, restype, argtypes in callbacks.values():
        out.append(f"{python_name} = ctypes.CFUNCTYPE({', '.join([restype] + argtypes)})")
    out += ["", "# ---- functions: name -> (restype, argtypes, parameter names) ----", "FUNCTIONS = {"]
    for name, restype, argtypes, names in functions:
        out.append(f'    "{name}": ({restype}, [{", ".join(argtypes)}], {tuple(names)!r}),')
    out += ["}",
            "",
            "",
            "def declare(library):",
            '    """Sets restype and argtypes of every function of `library` (a ctypes.CDLL of libdbs):',
            '    a function left with the default int return would truncate 64-bit pointers."""',
            "    for name, (restype, argtypes, _names) in FUNCTIONS.items():",
            "        function = getattr(library, name)",
            "        function.restype = restype",
            "        function.argtypes = argtypes",
            "    return library",
            ""]
    return "\n".join(out)


def generate(header_text, output):
    """The text `output` should hold, by its extension."""
    if output.endswith(".py"):
        return render(*read_header(header_text))
    if output.endswith(".inc"):
        return fortran_bindings.render(header_text)
    raise SystemExit(f"generate_bindings: {output}: an output ends in .py (ctypes) or .inc (Fortran)")


def main(argv):
    check = argv[:1] == ["--check"]
    if check:
        argv = argv[1:]
    if len(argv) < 2:
        raise SystemExit(__doc__)
    header, outputs = argv[0], argv[1:]
    with open(header, encoding="utf-8") as f:
        header_text = f.read()
    differing = 0
    for output in outputs:
        text = generate(header_text, output)
        if check:
            with open(output, encoding="utf-8") as f:
                committed = f.read()
            if committed != text:
                print(f"generate_bindings: {output} differs from what include/dbs.h gives: run scripts/generate_bindings.py {header} {output}")
                differing += 1
            else:
                print(f"generate_bindings: {output} matches {header}")
            continue
        with open(output, "w", encoding="utf-8") as f:
            f.write(text)
    return 1 if differing else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
