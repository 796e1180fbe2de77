"""charts.load validates before it builds: hostile or damaged files (a JSON attribute nested
100,000 deep, broken JSON, a missing variable, text where numbers belong, a dimension of 2⁴⁰
elements, damaged bytes) are refused with one ValueError line naming the file and the
variable or attribute, before any data is allocated."""
import re
import shutil
import time

import pytest

import charts
from charts.io.archive import load

xr = pytest.importorskip("xarray")
h5netcdf = pytest.importorskip("h5netcdf")


@pytest.fixture(scope="module")
def valid(tmp_path_factory):
    """A trajectory's file, as ``save`` writes it."""
    system = charts.RotorSystem(3)
    theta, u = system.random_state(0)
    path = tmp_path_factory.mktemp("valid") / "valid.nc"
    charts.integrate(system, theta, u, 1.0).save(path)
    return path


def _refused(path, pattern):
    """The one-line ValueError of ``load(path)``, which names the file and matches ``pattern``."""
    with pytest.raises(ValueError) as info:
        load(path)
    message = str(info.value)
    assert "\n" not in message and len(message) < 400, message
    assert str(path) in message, message
    assert re.search(pattern, message), message
    return message


def _rewritten(valid, tmp_path, change):
    """A copy of the valid file through xarray, ``change(ds)`` applied."""
    ds = xr.load_dataset(valid, engine="h5netcdf")
    changed = change(ds)
    ds = changed if isinstance(changed, xr.Dataset) else ds
    path = tmp_path / "hostile.nc"
    ds.to_netcdf(path, engine="h5netcdf")
    return path


def _attribute(valid, tmp_path, name, value):
    """A copy of the valid file with the attribute ``name`` set to ``value`` in place (h5netcdf)."""
    path = tmp_path / "hostile.nc"
    shutil.copyfile(valid, path)
    with h5netcdf.File(path, "a") as f:
        f.attrs[name] = value
    return path


def test_the_valid_file_loads(valid):
    assert load(valid).theta.shape[1] == 3


def test_json_nested_100000_deep_is_refused_before_parsing(valid, tmp_path):
    deep = "json:" + "[" * 100_000 + "]" * 100_000
    path = _attribute(valid, tmp_path, "status", deep)
    _refused(path, r"attribute 'status': JSON nested 100000 levels deep \(at most 64\)")


def test_json_at_the_depth_limit_is_read(valid, tmp_path):
    path = _attribute(valid, tmp_path, "status", "json:" + "[" * 64 + "]" * 64)
    status = load(path).status
    for _ in range(63):
        (status,) = status
    assert status == []


def test_broken_json_names_the_attribute(valid, tmp_path):
    path = _attribute(valid, tmp_path, "status", 'json:{"a": ')
    _refused(path, r"attribute 'status': broken JSON")


def test_a_missing_variable_is_named(valid, tmp_path):
    path = _rewritten(valid, tmp_path, lambda ds: ds.drop_vars("u"))
    _refused(path, r"the trajectory variable 'u' is missing")


def test_text_where_numbers_belong_is_refused(valid, tmp_path):
    def as_text(ds):
        ds["theta"] = ds["theta"].astype(str)
    path = _rewritten(valid, tmp_path, as_text)
    _refused(path, r"variable 'theta' holds text, not numbers")


def test_a_number_attribute_held_as_text_is_refused(valid, tmp_path):
    path = _attribute(valid, tmp_path, "n_steps", "7")
    _refused(path, r"attribute 'n_steps' = '7' is not integer")


def test_a_missing_attribute_is_named(valid, tmp_path):
    path = _rewritten(valid, tmp_path, lambda ds: ds.attrs.pop("method"))
    _refused(path, r"the trajectory attribute 'method' is missing")


def test_wrong_dimensions_are_named(valid, tmp_path):
    def renamed(ds):
        ds["u"] = (("t", "axis"), ds["u"].values)
    path = _rewritten(valid, tmp_path, renamed)
    _refused(path, r"variable 'u' has dimensions \('t', 'axis'\), not \('t', 'rotor'\)")


def test_an_unknown_kind_is_named(valid, tmp_path):
    path = _attribute(valid, tmp_path, "charts_kind", "nonsense")
    _refused(path, r"is not a charts result \(charts_kind = 'nonsense'")


def test_a_dimension_of_2_to_the_40_is_refused_without_allocating(valid, tmp_path):
    """An unlimited dimension resized to 2⁴⁰: a file of some KiB declares 24 TiB of theta."""
    ds = xr.load_dataset(valid, engine="h5netcdf")
    path = tmp_path / "huge.nc"
    ds.to_netcdf(path, engine="h5netcdf", unlimited_dims=["t"])
    with h5netcdf.File(path, "a") as f:
        f.resize_dimension("t", 2 ** 40)
    assert path.stat().st_size < 1 << 20
    start = time.monotonic()
    _refused(path, r"variable '\w+' declares shape \(1099511627776(, 3)?,?\) \([\d.]+ TiB\), "
                   r"more than a file of [\d.]+ KiB can hold \(1024× its size\)")
    assert time.monotonic() - start < 30


@pytest.mark.parametrize("signature, nth", [(b"OHDR", 0), (b"OHDR", 1), (b"OHDR", 3),
                                            (b"FRHP", 0)])
def test_damaged_bytes_give_one_line_naming_the_file(valid, tmp_path, capfd, signature, nth):
    """64 bytes flipped inside an HDF5 object header or heap (found by its signature): HDF5's
    own error (KeyError, RuntimeError...) becomes the one line, and nothing is printed."""
    data = bytearray(valid.read_bytes())
    at = [m.start() for m in re.finditer(re.escape(signature), bytes(data))]
    if len(at) <= nth:
        pytest.skip(f"this HDF5 writes fewer than {nth + 1} {signature!r} blocks")
    k = at[nth] + 4
    data[k:k + 64] = bytes(b ^ 0xFF for b in data[k:k + 64])
    path = tmp_path / "damaged.nc"
    path.write_bytes(bytes(data))
    capfd.readouterr()
    _refused(path, r"could not be read as NetCDF-4 \(is it truncated or damaged\?\): \w+")
    out, err = capfd.readouterr()
    assert out == "" and err == "", (out, err)


def test_every_kind_load_knows_has_its_schema():
    """`charts.load` builds the kinds of `KINDS`; the layout check knows a kind by its schema:
    the two tables name the same kinds."""
    from charts.io.archive import KINDS
    from charts.io.file_checks import SCHEMAS
    assert set(SCHEMAS) == set(KINDS)


@pytest.mark.parametrize("name", ["theta", "u", "t"])
def test_one_flipped_bit_of_data_is_refused_naming_the_variable(valid, tmp_path, name):
    """One bit flipped in the middle of a variable's numbers (found by their bytes): its HDF5
    checksum (Fletcher-32, written by ``save``) fails, and the line names the variable,
    where without it a wrong number would have loaded."""
    import numpy as np
    values = np.ascontiguousarray(xr.load_dataset(valid, engine="h5netcdf")[name].values)
    middle = values.ravel()[values.size // 2:values.size // 2 + 2].tobytes()
    data = bytearray(valid.read_bytes())
    k = data.find(middle)
    assert k > 0 and data.find(middle, k + 1) < 0             # found once
    data[k + 5] ^= 0x04
    path = tmp_path / "flipped.nc"
    path.write_bytes(bytes(data))
    _refused(path, rf"the data of variable '{name}' is damaged")
