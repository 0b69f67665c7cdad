"""The package as installed: its files, its type stub, its docstrings."""
import ast
import inspect
import os

import mcmd

PACKAGE = os.path.dirname(mcmd.__file__)


def stub():
    with open(os.path.join(PACKAGE, "__init__.pyi"), encoding="utf-8") as f:
        return ast.parse(f.read())


def test_package_files():
    names = os.listdir(PACKAGE)
    assert "py.typed" in names and "__init__.pyi" in names
    assert any(n.startswith("_mcmd.") and n.endswith(".so") for n in names)


def test_stub_matches_the_functions():
    functions = {node.name: node for node in stub().body if isinstance(node, ast.FunctionDef)}
    public = [name for name in mcmd.__all__ if inspect.isfunction(getattr(mcmd, name))]
    assert sorted(functions) == sorted(public) == ["fill", "fill_file"]
    for name in public:
        node, sig = functions[name], inspect.signature(getattr(mcmd, name))
        stubbed = ([(a.arg, "POSITIONAL_OR_KEYWORD") for a in node.args.args]
                   + [(a.arg, "KEYWORD_ONLY") for a in node.args.kwonlyargs]
                   + [(node.args.kwarg.arg, "VAR_KEYWORD")])
        assert stubbed == [(p.name, p.kind.name) for p in sig.parameters.values()], name
        # Every parameter and the return value are annotated.
        assert all(a.annotation is not None for a in node.args.args + node.args.kwonlyargs) and node.returns


def test_stub_names_the_exceptions_and_version():
    body = stub().body
    classes = {node.name: [ast.unparse(b) for b in node.bases] for node in body if isinstance(node, ast.ClassDef)}
    assert classes == {"Error": ["RuntimeError"], "Cancelled": ["Error"]}
    assert any(isinstance(node, ast.AnnAssign) and node.target.id == "__version__" for node in body)
    assert set(mcmd.__all__) == {"fill", "fill_file", "Error", "Cancelled", "__version__"}


def test_docstrings():
    for obj in (mcmd, mcmd.fill, mcmd.fill_file, mcmd.Error, mcmd.Cancelled):
        assert obj.__doc__ and len(obj.__doc__) > 40
    for word in ("Parameters", "Raises", "nodata", "mask", "rs"):
        assert word in mcmd.fill.__doc__


def test_dir_shows_the_api_and_dask_is_imported_on_first_use():
    import subprocess
    import sys
    code = ("import sys, mcmd; print(sorted(dir(mcmd))); print('dask' in sys.modules, 'xarray' in sys.modules); "
            "mcmd.dask.fill; print('mcmd.dask' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.split("\n")
    assert out[0] == str(sorted(["Cancelled", "Error", "__version__", "dask", "fill", "fill_file", "xarray"]))
    assert out[1:3] == ["False False", "True"]
    assert mcmd.fill.__module__ == "mcmd" and mcmd.fill_file.__module__ == "mcmd"


def libgomp_settings(**env):
    """libgomp's settings as it reports them when `import mcmd` loads it."""
    import subprocess
    import sys
    environ = {k: v for k, v in os.environ.items() if k not in ("OMP_WAIT_POLICY", "GOMP_SPINCOUNT")}
    environ.update(env, OMP_DISPLAY_ENV="verbose")
    return subprocess.run([sys.executable, "-c", "import mcmd"], capture_output=True, text=True, check=True,
                          env=environ).stderr


def test_openmp_waits_passively_unless_the_user_chose():
    # Passive is a spin count of 0 (libgomp's own default, 300000, also shows 'PASSIVE').
    assert "GOMP_SPINCOUNT = '0'" in libgomp_settings()
    assert "OMP_WAIT_POLICY = 'ACTIVE'" in libgomp_settings(OMP_WAIT_POLICY="active")
    assert "GOMP_SPINCOUNT = '1000'" in libgomp_settings(GOMP_SPINCOUNT="1000")
