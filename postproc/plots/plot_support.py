"""What the plot scripts of postproc/plots share: their command line, the reading of blockfrag's
HDF5 outputs, and how a script ends.

A script imports this module from its own folder (the source tree's postproc/plots, or an install's
share/blockfrag/plots), before pyplot: importing it selects matplotlib's file-only backend.

    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import plot_support  # noqa: E402

Errors: a reader raises InputError with one line naming the file and what is wrong in it (the
dataset, the attribute, the column); a writer raises OutputError naming the file it cannot write.
run() turns them into that line on stderr and exit code 2 (bad input, as blockfrag and argparse
use it) or 1 (an output that cannot be written), without a traceback.
"""

import argparse
import contextlib
import os
import sys

import matplotlib

matplotlib.use("Agg")
import h5py  # noqa: E402  (the backend must be chosen before pyplot, and h5py is grouped here)
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

EXIT_BAD_INPUT = 2
EXIT_OUTPUT_FAILURE = 1


class InputError(Exception):
    """A problem with an input file or an option's value, reported as one line without a traceback."""


class OutputError(Exception):
    """An output file that cannot be written, reported as one line without a traceback."""


# --- The command line ---------------------------------------------------------------------------

def parser(doc):
    """An argument parser described by the first line of the script's docstring."""
    return argparse.ArgumentParser(description=doc.splitlines()[0])


def add_output(arguments, required=False):
    arguments.add_argument("-o", "--output", required=required, help="PNG file to write")


def add_title(arguments, default="from the file name"):
    arguments.add_argument("--title", help=f"figure title (default: {default})")


def run(work):
    """Runs work() and returns the script's exit code: 0; 2 after an InputError, 1 after an
    OutputError or another system error, each reported as one line on stderr."""
    name = os.path.basename(sys.argv[0])
    try:
        work()
    except InputError as error:
        print(f"{name}: error: {error}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except BrokenPipeError:
        # The reader of what the script prints went away (| head): nothing left to say.
        sys.stderr.close()
        return EXIT_OUTPUT_FAILURE
    except OutputError as error:
        print(f"{name}: error: {error}", file=sys.stderr)
        return EXIT_OUTPUT_FAILURE
    except OSError as error:
        print(f"{name}: error: {error.strerror or error}", file=sys.stderr)
        return EXIT_OUTPUT_FAILURE
    return 0


# --- Writing ------------------------------------------------------------------------------------

@contextlib.contextmanager
def writing(path):
    """An OSError inside the block becomes an OutputError naming `path`."""
    try:
        yield
    except OSError as error:
        raise OutputError(f"cannot write {path}: {error.strerror or error}") from error


def save_figure(figure, path, dpi):
    """The figure as a PNG at `path`; the figure is closed either way."""
    try:
        with writing(path):
            figure.savefig(path, dpi=dpi)
    finally:
        plt.close(figure)


# --- Reading HDF5 -------------------------------------------------------------------------------

def open_hdf5(path):
    """The file, open for reading (use it in a with statement); an InputError when it does not
    exist or is not HDF5."""
    if not os.path.exists(path):
        raise InputError(f"{path}: no such file")
    try:
        return h5py.File(path, "r")
    except OSError as error:
        raise InputError(f"{path}: not a readable HDF5 file ({error})") from error


def has_group(file, name):
    return name in file and isinstance(file[name], h5py.Group)


def has_dataset(file, name):
    return name in file and isinstance(file[name], h5py.Dataset)


def dataset(file, path, name, dtype=float, hint=None):
    """The dataset `name` as a numpy array of `dtype`; an InputError naming the file and the dataset
    when it is missing or not numbers (`hint` says what kind of file was expected)."""
    if not has_dataset(file, name):
        raise InputError(f"{path} has no dataset {name}" + (f" (is it {hint}?)" if hint else ""))
    try:
        return np.asarray(file[name][()], dtype=dtype)
    except (TypeError, ValueError, OSError) as error:
        raise InputError(f"{path}: dataset {name} cannot be read as numbers ({error})") from error


def attribute(node, path, name, convert=None):
    """The attribute `name` of a file, group or dataset, through `convert` (text, float, ...); an
    InputError naming the file, the object and the attribute when it is missing or of another
    kind."""
    if name not in node.attrs:
        raise InputError(f"{path}: {node.name} has no attribute {name}")
    value = node.attrs[name]
    if convert is None:
        return value
    try:
        return convert(value)
    except (TypeError, ValueError) as error:
        raise InputError(f"{path}: attribute {name} of {node.name} cannot be read ({error})") from error


def text(value):
    """An attribute as str: h5py gives str for variable-length strings, bytes for fixed-length ones."""
    if isinstance(value, bytes):
        return value.decode("utf-8", "replace")
    if isinstance(value, np.ndarray) and value.shape == ():
        return text(value[()])
    return str(value)
