"""onetip.SensorOptions against the option table (label options).

The reference is the table as the C ABI describes it (onetip_option_count and
onetip_option_describe, called through ctypes in the libonetip this module
loaded), so these checks do not go through the Python binding's own code:
the attributes are exactly the table's names, each default equals the table's,
values at min and max are accepted, values just outside (the next double, or
the next integer) are refused with InputError naming the option, and so is a
choice outside its names. option_table() repeats the C rows exactly.
"""
import ctypes
import math

import pytest

import onetip

TYPES = {0: "integer", 1: "real", 2: "flag", 3: "choice", 4: "axes"}


class _Info(ctypes.Structure):
    _fields_ = [("name", ctypes.c_char * 48), ("type", ctypes.c_int32), ("count", ctypes.c_int32),
                ("min", ctypes.c_double), ("max", ctypes.c_double), ("default_value", ctypes.c_double * 6),
                ("unit", ctypes.c_char * 16), ("choices", ctypes.c_char * 96), ("doc", ctypes.c_char * 128)]


class _Error(ctypes.Structure):
    _fields_ = [("kind", ctypes.c_int32), ("message", ctypes.c_char * 256)]


def _loaded_libonetip():
    with open("/proc/self/maps") as maps:
        for line in maps:
            path = line.split()[-1]
            if "/libonetip.so" in path:
                return ctypes.CDLL(path)
    pytest.fail("libonetip is not loaded by the onetip module")


@pytest.fixture(scope="module")
def c_table():
    lib = _loaded_libonetip()
    lib.onetip_abi_version.restype = ctypes.c_uint32
    abi = lib.onetip_abi_version()
    rows = []
    for i in range(lib.onetip_option_count()):
        info, error = _Info(), _Error()
        assert lib.onetip_option_describe(ctypes.c_uint32(abi), ctypes.c_int32(i), ctypes.byref(info),
                                          ctypes.byref(error)) == 0, error.message
        rows.append({"name": info.name.decode(), "type": TYPES[info.type], "count": info.count, "min": info.min,
                     "max": info.max, "default": list(info.default_value)[:info.count], "unit": info.unit.decode(),
                     "choices": info.choices.decode().split() if info.choices else [], "doc": info.doc.decode()})
    assert len(rows) > 0
    return rows


def _as_values(value):
    """A Python attribute value as the table's list of doubles."""
    if isinstance(value, list):
        return [float(v) for v in value]
    return [float(int(value))] if isinstance(value, (bool, onetip.FilterKind)) else [float(value)]


def _with(row, k, v):
    """The Python value that sets value k of a row to v (whole lists for axes)."""
    if row["type"] == "axes":
        values = list(row["default"])
        values[k] = v
        return values
    if row["type"] in ("integer", "choice"):
        return int(v)
    return float(v)


def _outside(row):
    if row["type"] in ("integer", "choice"):
        return row["min"] - 1, row["max"] + 1
    return math.nextafter(row["min"], -math.inf), math.nextafter(row["max"], math.inf)


def test_the_attributes_are_exactly_the_tables_options(c_table):
    attributes = {name for name, v in vars(onetip.SensorOptions).items() if isinstance(v, property)}
    assert attributes == {r["name"] for r in c_table}


def test_option_table_repeats_the_c_rows(c_table):
    rows = onetip.SensorOptions.option_table()
    assert [r.name for r in rows] == [r["name"] for r in c_table]
    for py, c in zip(rows, c_table):
        assert (py.type, py.count, py.min, py.max, py.unit, py.doc, py.choices) == (
            c["type"], c["count"], c["min"], c["max"], c["unit"], c["doc"], c["choices"]), c["name"]
        assert _as_values(py.default) == c["default"], c["name"]


def test_defaults_equal_the_tables(c_table):
    options = onetip.SensorOptions()
    for row in c_table:
        assert _as_values(getattr(options, row["name"])) == row["default"], row["name"]


def test_values_at_the_bounds_are_accepted_and_just_outside_refused(c_table):
    checked = 0
    for row in c_table:
        if row["type"] == "flag":
            continue  # a Python bool cannot leave 0..1
        low, high = _outside(row)
        for k in range(row["count"]):
            options = onetip.SensorOptions()
            for bound in (row["min"], row["max"]):
                setattr(options, row["name"], _with(row, k, bound))
                assert _as_values(getattr(options, row["name"]))[k] == bound, row["name"]
            for bad in (low, high):
                before = _as_values(getattr(options, row["name"]))
                with pytest.raises(onetip.InputError, match=row["name"]):
                    setattr(options, row["name"], _with(row, k, bad))
                assert _as_values(getattr(options, row["name"])) == before, "a refused value changed the option"
                checked += 1
        with pytest.raises(onetip.InputError, match=row["name"]):
            onetip.SensorOptions(**{row["name"]: _with(row, 0, high)})
    assert checked >= 2 * len(c_table)


def test_choices_take_their_names_and_refuse_others(c_table):
    for row in (r for r in c_table if r["type"] == "choice"):
        options = onetip.SensorOptions()
        for value, name in enumerate(row["choices"]):
            setattr(options, row["name"], name)
            assert _as_values(getattr(options, row["name"])) == [value]
        with pytest.raises(onetip.InputError, match=row["name"]):
            setattr(options, row["name"], "bogus")


def test_axis_arrays_need_six_values():
    with pytest.raises(onetip.InputError, match="gain"):
        onetip.SensorOptions(gain=[1, 2, 3])
