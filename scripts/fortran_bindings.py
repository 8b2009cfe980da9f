"""The Fortran half of scripts/generate_bindings.py: the constants and bind(C) interface blocks of
dbs.h as a Fortran 2008 include file (fortran/dbs_capi.inc), INCLUDEd by the module in
fortran/dbs.f90.

The map from dbs.h:
  - DBS_OK and DBS_ERR_* -> integer(c_int) (statuses are C ints); a value with a decimal point ->
    real(c_double); every other constant -> integer(c_int32_t) (the ids are int32_t arguments);
  - int, int32_t, size_t, double -> integer(c_int), integer(c_int32_t), integer(c_size_t),
    real(c_double), passed by value;
  - handles (dbs_x *, const dbs_x *, void *) -> type(c_ptr), value; out-handles (dbs_x **) ->
    type(c_ptr), intent(out); callbacks (dbs_*_fn) -> type(c_funptr), value;
  - const char * parameters -> character(kind=c_char), intent(in) :: s(*) (NUL-terminated:
    dbs_c_string); a returned const char * -> type(c_ptr) (dbs_f_string);
  - pointers to data: an assumed-size array (*) when a size_t count (capacity, count, n, n_*)
    follows it or its name says it is an array (ARRAY_NAMES, ARRAYS), else a scalar; intent(in)
    when const, intent(out) otherwise;
  - pointers the header allows to be NULL (NULLABLE) -> type(c_ptr), value: Fortran 2008 has no
    OPTIONAL in BIND(C); pass c_loc(x) or c_null_ptr (the module's hand-written wrappers take
    OPTIONAL arguments instead);
  - void functions -> subroutines; callback typedefs -> abstract interfaces of the same name.
"""
import re

# Parameter names that are arrays whatever follows them.
ARRAY_NAMES = {"xyz", "uv", "out_xyz", "out_uv", "out_normal", "out_su", "out_sv", "out_rect",
               "corners", "corners_xyz", "triangles", "bottom", "right", "top", "left"}
# (function, parameter) pairs that are arrays although their name is also used for scalars.
ARRAYS = {("dbs_cloud_bounds", "out_min"), ("dbs_cloud_bounds", "out_max")}
# (function, parameter) pairs dbs.h documents as "may be NULL" / "when not NULL".
NULLABLE = {
    ("dbs_boundary_create_tolerant", "out_max_snap"),
    ("dbs_boundary_load_tolerant", "out_max_snap"),
    ("dbs_result_evaluate", "out_normal"),
    ("dbs_result_evaluate_many", "out_normal"),
    ("dbs_result_evaluate_many", "out_su"),
    ("dbs_result_evaluate_many", "out_sv"),
}
COUNT_NAME = re.compile(r"capacity|count|n|n_\w+")
SCALARS = {"int": "integer(c_int)", "int32_t": "integer(c_int32_t)",
           "size_t": "integer(c_size_t)", "double": "real(c_double)"}
KIND_OF = {"integer(c_int)": "c_int", "integer(c_int32_t)": "c_int32_t",
           "integer(c_size_t)": "c_size_t", "real(c_double)": "c_double",
           "type(c_ptr)": "c_ptr", "type(c_funptr)": "c_funptr", "character(kind=c_char)": "c_char"}
LINE = 100  # longest line written (free form allows 132)


def split_parameter(parameter):
    """'const double *xyz' -> ('const double *', 'xyz'); a `struct` tag is dropped (the header
    names a struct before its typedef as `struct dbs_options`). Shared by both outputs."""
    match = re.fullmatch(r"(.*?)(\w+)", parameter.strip())
    if not match:
        raise SystemExit(f"generate_bindings: cannot read parameter '{parameter}'")
    return re.sub(r"\bstruct\s+", "", re.sub(r"\s+", " ", match.group(1).strip())), match.group(2)


def parameters_of(text):
    text = text.strip()
    return [] if text in ("", "void") else [split_parameter(p) for p in text.split(",")]


def declaration(function, params, index, callbacks, is_callback=False):
    """The Fortran declaration (type-spec, attributes, shape) of parameter `index` of `function`."""
    c_type, name = params[index]
    if c_type in SCALARS:
        return SCALARS[c_type], ", value", ""
    if c_type in callbacks:
        return "type(c_funptr)", ", value", ""
    if c_type == "const char *" and not is_callback:
        return "character(kind=c_char)", ", intent(in)", "(*)"
    if c_type in ("void *", "const char *") or re.fullmatch(r"(const )?dbs_\w+ \*", c_type):
        return "type(c_ptr)", ", value", ""
    if re.fullmatch(r"(const )?dbs_\w+ \*\*", c_type):
        return "type(c_ptr)", ", intent(out)", ""
    match = re.fullmatch(r"(const )?(int32_t|size_t|double) \*", c_type)
    if not match:
        raise SystemExit(f"generate_bindings: no Fortran type for C type '{c_type}' ({function})")
    if (function, name) in NULLABLE:
        return "type(c_ptr)", ", value", ""
    intent = ", intent(in)" if match.group(1) else ", intent(out)"
    following = params[index + 1] if index + 1 < len(params) else None
    counted = following is not None and following[0] == "size_t" and COUNT_NAME.fullmatch(following[1])
    array = counted or name in ARRAY_NAMES or (function, name) in ARRAYS
    return SCALARS[match.group(2)], intent, "(*)" if array else ""


def result_type(c_type):
    c_type = re.sub(r"\s+", " ", c_type.strip())
    if c_type == "const char *":
        return "type(c_ptr)"
    if c_type in SCALARS:
        return SCALARS[c_type]
    raise SystemExit(f"generate_bindings: no Fortran result type for C type '{c_type}'")


def wrapped(first, words, last, indent):
    """`first` + words joined by ', ' + ')' + `last`, continued with '&' on lines of at most
    LINE characters; `last` moves to a line of its own when it does not fit."""
    lines, line = [], first
    for i, word in enumerate(words):
        piece = word + (", " if i + 1 < len(words) else ")")
        if len(line) + len(piece) + 2 > LINE:
            lines.append(line.rstrip() + " &")
            line = indent + "    "
        line += piece
    if not words:
        line += ")"
    if len(line) + len(last) + 3 > LINE:
        lines.append(line + " &")
        line = indent + "   "
    lines.append(line + " " + last)
    return lines


def procedure(name, c_return, params, callbacks, binding, indent="  "):
    """An interface body for a prototype (binding: the bind(C) clause). The strings a callback
    receives are type(c_ptr) (dbs_f_string reads them): their length is not known."""
    names = [p[1] for p in params]
    is_function = c_return.strip() != "void"
    keyword = "function" if is_function else "subroutine"
    lines = wrapped(f"{indent}{keyword} {name}(", names, binding, indent)
    is_callback = name.endswith("_fn")
    declarations = [declaration(name, params, i, callbacks, is_callback) for i in range(len(params))]
    if is_function:
        declarations.append((result_type(c_return), "", ""))
    kinds = sorted({KIND_OF[d[0]] for d in declarations})
    if kinds:
        lines.append(f"{indent}  import :: {', '.join(kinds)}")
    for (type_spec, attributes, shape), parameter in zip(declarations, names + [name]):
        lines.append(f"{indent}  {type_spec}{attributes} :: {parameter}{shape}")
    lines.append(f"{indent}end {keyword} {name}")
    return lines


def constant(name, value):
    if "." in value or "e" in value.lower():
        return f"real(c_double), parameter :: DBS_{name} = {value}_c_double"
    if name == "OK" or name.startswith("ERR_"):
        return f"integer(c_int), parameter :: DBS_{name} = {value}"
    return f"integer(c_int32_t), parameter :: DBS_{name} = {value}"


def section_title(line):
    match = re.match(r"/\* ---- (.*?) ?(\([^)]*\))? -+ \*/", line)
    return match.group(1) if match else None


def read_header(text):
    """(constant lines, callback interfaces, function interfaces), each with the header's
    section headings as comments, in the header's order."""
    callbacks = dict((name, (ret, params)) for ret, name, params in
                     re.findall(r"^typedef\s+(.*?)\(\*\s*(dbs_\w+_fn)\)\((.*)\);", text, re.MULTILINE))
    constants, functions, section = [], [], None
    seen = {}
    for line in text.splitlines():
        title = section_title(line)
        if title:
            section = title
            continue
        match = re.match(r"#define\s+DBS_(\w+)\s+(-?[0-9][0-9.eE+-]*)\b", line)
        if match:
            constants.append((section, constant(*match.groups())))
            continue
        match = re.match(r"\s*DBS_API\s+(.*?)\b(dbs_\w+)\s*\((.*)\)\s*;", line)
        if match:
            ret, name, params = match.groups()
            params = parameters_of(params)
            seen[name] = {p[1] for p in params}
            functions.append((section, procedure(name, ret, params, callbacks, f'bind(C, name="{name}")')))
    for function, parameter in NULLABLE | ARRAYS:
        if parameter not in seen.get(function, ()):
            raise SystemExit(f"generate_bindings: {function}({parameter}) of the tables is not in dbs.h")
    abstract = []
    for name, (ret, params) in callbacks.items():
        abstract += procedure(name, ret, parameters_of(params), {}, "bind(C)")
    return constants, abstract, functions


def with_headings(entries, indent):
    """The entries (section, line or lines) with a comment line opening each section."""
    out, current = [], None
    for section, lines in entries:
        if section != current:
            out += ["", f"{indent}! ---- {section}"]
            current = section
        out += lines if isinstance(lines, list) else [indent + lines]
    return out


def render(text):
    constants, abstract, functions = read_header(text)
    out = ["! The C API of libdbs for Fortran 2008: every constant and function of dbs.h, INCLUDEd by",
           "! the module dbs (fortran/dbs.f90), which needs `use, intrinsic :: iso_c_binding`.",
           "!",
           "! Generated from include/dbs.h by scripts/generate_bindings.py: do not edit (a test",
           "! compares this file with what the script writes). Indices (points, patches, sides,",
           "! holes) start at 0, as in the C API."]
    out += with_headings(constants, "")
    out += ["", "! ---- callback types (for procedure(...) declarations; pass c_funloc(f))",
            "abstract interface"] + abstract + ["end interface"]
    out += ["", "interface"] + with_headings(functions, "  ")[1:] + ["end interface", ""]
    return "\n".join(out)
