"""Checks that the Fortran module binds every function of dbs.h with the right number of
arguments and every numeric constant with its value, so that nothing added to the header can
be forgotten. (The Python package's declarations are generated from dbs.h:
scripts/generate_bindings.py.)

usage: check_bindings.py DBS_H DBS_MODULE_F90
"""
import re
import sys


def header_functions(text):
    """name -> number of parameters, for every DBS_API prototype (each sits on one line)."""
    functions = {}
    for line in text.splitlines():
        match = re.match(r"\s*DBS_API\s+[^(]*?\b(dbs_\w+)\s*\((.*)\)\s*;", line)
        if match:
            parameters = match.group(2).strip()
            functions[match.group(1)] = 0 if parameters in ("", "void") else parameters.count(",") + 1
    return functions


def header_constants(text):
    """DBS_NAME -> value, for every `#define DBS_NAME <number>`."""
    return {name: float(value) for name, value in re.findall(r"^#define\s+(DBS_\w+)\s+(-?[0-9.]+)\b", text, re.MULTILINE)}


def fortran_constants(text):
    """DBS_NAME -> value, for every `parameter :: DBS_NAME = <number>` of the module."""
    constants = {}
    for line in text.splitlines():
        if "parameter" in line:
            for name, value in re.findall(r"\b(DBS_\w+)\s*=\s*(-?[0-9.]+)(?:[de][-+]?[0-9]+)?(?:_\w+)?", line, re.IGNORECASE):
                constants[name] = float(value)
    return constants


def compare_constants(language, expected, actual):
    problems = [f"{language}: {name} is missing" for name in sorted(set(expected) - set(actual))]
    problems += [f"{language}: {name} = {actual[name]:g}, dbs.h has {value:g}" for name, value in sorted(expected.items()) if name in actual and actual[name] != value]
    return problems


def fortran_functions(text):
    """name -> number of dummy arguments, for every bind(C, name="dbs_...") interface."""
    text = re.sub(r"&\s*\n\s*", " ", text)  # join continuation lines
    functions = {}
    pattern = r"(?:function|subroutine)\s+\w+\s*\(([^)]*)\)[^\n]*?bind\s*\(\s*C\s*,\s*name\s*=\s*\"(dbs_\w+)\"\s*\)"
    for match in re.finditer(pattern, text, re.IGNORECASE):
        arguments = match.group(1).strip()
        functions[match.group(2)] = 0 if not arguments else arguments.count(",") + 1
    return functions


def compare(language, expected, actual):
    problems = []
    for name, count in sorted(expected.items()):
        if name not in actual:
            problems.append(f"{language}: {name} is not bound")
        elif actual[name] != count:
            problems.append(f"{language}: {name} has {actual[name]} arguments, dbs.h has {count}")
    for name in sorted(set(actual) - set(expected)):
        problems.append(f"{language}: {name} is bound but not in dbs.h")
    return problems


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    with open(argv[1]) as header, open(argv[2]) as fortran:
        header_text, fortran_text = header.read(), fortran.read()
    expected = header_functions(header_text)
    problems = compare("dbs_module.f90", expected, fortran_functions(fortran_text))
    constants = header_constants(header_text)
    problems += compare_constants("dbs_module.f90", constants, fortran_constants(fortran_text))
    if len(expected) < 40 or len(constants) < 40:
        problems.append(f"only {len(expected)} prototypes and {len(constants)} constants found in {argv[1]}: the header parser is broken")
    for problem in problems:
        print(problem, file=sys.stderr)
    print(f"{len(expected)} functions and {len(constants)} constants of dbs.h checked in the Fortran module: {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
