"""The build's command line (`python build_fmu.py`, `cardan-joint build`): parse
the arguments, then call `builder.build`."""

import argparse
import sys
from pathlib import Path

from ..models import discover
from ..names import UsageError, parse_assignments
from .builder import DEFAULT_MODEL, FMI_VERSIONS, BuildError, build


def _add_setting(parser, setting: str, specs) -> None:
    """`--<setting>`, offered for the models whose spec declares the setting."""
    defaults = ", ".join(f"{s.key} {s.default_settings[setting]}" for s in specs)
    helps = {s.setting_help.get(setting) for s in specs} - {None}
    kind = type(specs[0].default_settings[setting])
    # A switch is `--<setting>` / `--no-<setting>`: argparse's type=bool would take
    # any text, "false" too, as true.
    how = (
        {"action": argparse.BooleanOptionalAction}
        if kind is bool
        else {"type": kind, "metavar": setting.upper()}
    )
    parser.add_argument(
        f"--{setting}",
        default=None,
        help=f"{'; '.join(sorted(helps)) or setting} (default: {defaults})",
        **how,
    )


def _model_key(text: str) -> str:
    """A model's name (its key) from its name or its folder's name (left as given if neither)."""
    models = discover()
    return next((key for key, spec in models.items() if text in (key, spec.folder)), text)


def _vectors(fmu: Path) -> bool | None:
    """Whether the FMU at `fmu` holds FMI 3 arrays (None: no readable FMU there)."""
    import zipfile

    from fmpy import read_model_description

    try:
        variables = read_model_description(str(fmu)).modelVariables
    except (zipfile.BadZipFile, KeyError, OSError, ValueError):  # none there, or not an FMU
        return None
    return any(getattr(v, "dimensions", None) for v in variables)


def main(argv=None, prog=None) -> int:
    parser = argparse.ArgumentParser(
        prog=prog,
        description=f"Build and validate an FMU of this project (default: the {DEFAULT_MODEL} "
        "FMU).",
    )
    parser.add_argument(
        "--model",
        default=DEFAULT_MODEL,
        type=_model_key,
        choices=sorted(discover()),
        help="which model to build, by its name or its folder's under models/ "
        "(default: %(default)s)",
    )
    parser.add_argument(
        "--fmi-version",
        type=int,
        default=2,
        choices=FMI_VERSIONS,
        help="FMI version (default: 2; FMI 3 goes to DEST/fmi3/)",
    )
    parser.add_argument(
        "--fmi3-arrays",
        action="store_true",
        help="FMI 3 only: a model's vectors (a table's array rows, e.g. a quaternion) "
        "as Float64 arrays, for hosts that read whole arrays; the default, "
        "scalars named as in FMI 2.0, every FMI 3 host reads (docs/fmi3.md). Written "
        "to the same file as the scalar build (the command says it replaced it): "
        "--name keeps both",
    )
    parser.add_argument("--dest", default="dist", help="output folder (default: dist)")
    parser.add_argument(
        "--name", default=None, help="model name and FMU file name (default: the model's own name)"
    )
    parser.add_argument(
        "--set",
        action="append",
        default=[],
        metavar="NAME=VALUE",
        help="start value of an input or parameter in SI units (rad, rad/s, N.m, kg.m2), "
        "e.g. --set bend_angle=0.2",
    )
    models = discover()
    for setting in sorted({name for spec in models.values() for name in spec.default_settings}):
        _add_setting(
            parser, setting, [spec for spec in models.values() if setting in spec.default_settings]
        )
    parser.add_argument(
        "--cross-check",
        action="store_true",
        help="also write DEST/cross-check/fmus/2.0/cs/linux64/... with the model's "
        "reference run (fmi-cross-check layout; a model whose spec declares one)",
    )
    args = parser.parse_args(argv)
    dest = Path(args.dest)
    blocking = next((p for p in (dest, *dest.parents) if p.exists() and not p.is_dir()), None)
    if blocking is not None:
        parser.error(f"--dest {args.dest}: {blocking} is a file, not a folder")
    if args.fmi3_arrays and args.fmi_version != 3:
        parser.error("--fmi3-arrays needs --fmi-version 3")
    spec = models[args.model]
    settings = {}
    for setting in sorted({name for s in models.values() for name in s.default_settings}):
        value = getattr(args, setting)
        if value is None:
            continue
        if setting not in spec.default_settings:
            parser.error(f"--{setting} does not apply to {args.model}")
        settings[setting] = value
    if args.cross_check and (
        spec.reference is None
        or args.fmi_version != 2
        or args.name not in (None, args.model)
        or args.set
        or settings
    ):
        parser.error(
            "--cross-check takes a model with a reference run "
            f"({', '.join(s.key for s in models.values() if s.reference)}), built for "
            "FMI 2 with its own name, start values and settings (no --fmi-version, "
            "--name, --set or settings): the reference run assumes them"
        )
    try:
        start_values = parse_assignments(args.set)
    except UsageError as error:
        parser.error(str(error))
    target = Path(args.dest, "fmi3" if args.fmi_version == 3 else "")
    target /= f"{args.name or spec.default_name({**spec.default_settings, **settings})}.fmu"
    earlier = _vectors(target)
    try:
        fmu = build(
            args.dest,
            args.name,
            start_values,
            model=args.model,
            settings=settings,
            fmi_version=args.fmi_version,
            fmi3_arrays=args.fmi3_arrays,
        )
    except BuildError as error:  # the user's mistake exits 2, as `cardan-joint simulate`'s
        print(f"{parser.prog}: {error}", file=sys.stderr)
        return 2 if isinstance(error, UsageError) else 1
    except OSError as error:  # a folder that cannot be written: named, no traceback
        print(
            f"{parser.prog}: {error.filename or args.dest}: {error.strerror or error}",
            file=sys.stderr,
        )
        return 1
    print(f"built and validated {fmu}")
    if earlier is not None and earlier != args.fmi3_arrays:
        kinds = ("scalars", "arrays") if args.fmi3_arrays else ("arrays", "scalars")
        print(
            f"replaced the earlier {fmu.name} of FMI 3 {kinds[0]} with FMI 3 {kinds[1]} "
            "(--name gives a build a file of its own)"
        )
    if args.cross_check:
        from .cross_check import write_cross_check

        print(f"wrote {write_cross_check(Path(args.dest) / 'cross-check', fmu, args.model)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
