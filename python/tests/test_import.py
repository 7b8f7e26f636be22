"""`import vssw` loads the package's first page only: the typed API, its results, vssw.cli and the compiled part are
imported when first named (vssw/__init__.py, _LAZY), and with them the standard modules they bring; what a name gives
is the same object whether it was imported eagerly or not. Not timed: the modules loaded are what is checked."""
import subprocess
import sys

# Loaded by the modules the package defers, and by none of the package's first page or NumPy: each would be a cost
# of `import vssw` paid by scripts that use none of it.
DEFERRED = ["vssw._api", "vssw._results", "vssw.cli", "vssw._core", "vssw._study_records", "tempfile", "decimal",
            "dataclasses", "subprocess", "matplotlib", "pandas"]


def loaded_after(code):
    """The names of DEFERRED in sys.modules after `import vssw` and `code`, in a new interpreter."""
    done = subprocess.run([sys.executable, "-c", f"import sys, vssw; {code}; "
                           f"print(' '.join(m for m in {DEFERRED!r} if m in sys.modules))"],
                          capture_output=True, text=True, check=True)
    return done.stdout.split()


def test_import_vssw_loads_none_of_the_deferred_modules():
    assert loaded_after("pass") == []


def test_the_check_sees_a_deferred_module_once_a_name_needs_it():
    # What must fail the check above: naming a function of the typed API loads the API, its results and the compiled part.
    loaded = loaded_after("vssw.simulate")
    for module in ["vssw._api", "vssw._results", "vssw._core", "tempfile", "dataclasses"]:
        assert module in loaded, loaded


def test_the_errors_need_nothing_deferred():
    # The exceptions are on the first page: catching vssw.InputError costs no import.
    assert loaded_after("vssw.InputError, vssw.Error, vssw.SimulationError, vssw.BoundsError") == []


def test_each_name_is_the_object_of_the_module_that_holds_it():
    import vssw
    from vssw import _api, _core, _results, cli

    assert vssw.simulate is _api.simulate and vssw.Comparison is _results.Comparison
    assert vssw.free is cli.free and vssw.cli is cli
    assert vssw.__version__ == _core.VERSION and vssw.__commit__ == _core.COMMIT
    assert set(vssw.__all__) <= set(dir(vssw))


def test_a_name_the_package_lacks_is_an_attribute_error():
    import vssw

    try:
        vssw.no_such_name  # noqa: B018
    except AttributeError as e:
        assert "no_such_name" in str(e)
    else:
        raise AssertionError("no AttributeError")
