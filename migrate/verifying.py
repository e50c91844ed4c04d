"""``mint-migrate --verify``: the options of the mode, each application verified, the report printed.

The comparison itself is ``verification``; this module turns the command line
into its settings (the scenario files read as written for the v3 original) and
the migrated applications into the report ``verification.report`` prints.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING

from mintlang.dialect import Dialect
from mintlang.migrate import verification
from mintlang.migrate.applications import Migrated, UsageError
from mintlang.migrate.model import MigrationResult
from mintlang.migrate.verification import report as verification_report
from mintlang.migrate.verification.report import Verified
from mintlang.records import record
from mintlang.runtime import scenario as scenarios
from mintlang.runtime.hardware import machine

if TYPE_CHECKING:
    from rich.console import Console

    from mintlang.migrate.verification import Verification
    from mintlang.runtime.scenario import Scenario

# ``verification`` and ``scenarios`` import each name when it is first used (``mintlang.lazy``): without
# ``--verify``, mint-migrate checks only ``Options.refuse`` and loads neither the simulator nor the scenarios.


@record
class Settings:
    """What each application is verified with."""

    v3_controller: str
    controller: str
    scenario: Scenario
    until_ms: int
    to: str = "v4"  # "mintmt": the originals are Mint v4 on ``controller``, the migrations MintMT


@record
class Options:
    """The command line's ``--verify`` options, as given (None: not given)."""

    scenario_paths: tuple[Path, ...]
    until_ms: int | None
    v3_controller: str | None
    drives: str | None

    def settings(self, controller: str, to: str = "v4") -> Settings:
        """The settings, with the scenario files read; one that cannot be read or used is a ``UsageError``."""
        v3_controller = self.v3_controller or verification.V3_DEFAULT
        scenario = (
            scenarios.Scenario(drives=(scenarios.DrivesEnabled(),))
            if self.drives == "enabled"
            else scenarios.Scenario()
        )
        # the stimulus is written for the original: v3 on its controller, or v4 on the target's (--to mintmt)
        original = (controller, Dialect.V4) if to == "mintmt" else (v3_controller, Dialect.V3)
        simulated = machine(*original)
        for path in self.scenario_paths:
            try:
                scenario = scenarios.merge(scenario, scenarios.load_scenario(path, simulated, original[1]))
            except scenarios.ScenarioFileError as error:
                raise UsageError(str(error).replace("\n", "; ")) from None
            except OSError as error:
                raise UsageError(f"cannot read {path}: {error.strerror or error}") from None
        return Settings(v3_controller, controller, scenario, self.until_ms or verification.DEFAULT_UNTIL_MS, to)

    def refuse(self, typed: Callable[[str], bool]) -> None:
        """Without ``--verify``: any of its options typed on the command line is a ``UsageError``; a settings
        file's defaults for them are not (``typed`` tells which, by parameter name)."""
        given = {"--scenario": ("scenario_paths", self.scenario_paths), "--until-ms": ("until_ms", self.until_ms)}
        given |= {"--v3-controller": ("v3_controller", self.v3_controller), "--drives": ("drives", self.drives)}
        named = [flag for flag, (parameter, value) in given.items() if value and typed(parameter)]
        if named:
            raise UsageError(f"{', '.join(named)}: only with --verify")


def verify_all(migrated: list[list[Migrated]], settings: Settings) -> tuple[list[Verified], list[str]]:
    """Each application migrated without a failure, verified; a ``REM @sim`` line that cannot be read is a
    problem of that application alone."""
    verified, problems = [], []
    for files in migrated:
        result = _whole(files)
        if result is None:
            continue  # its failure is reported with the migration's
        paths = {item.entry.role: item.entry.path for item in files}
        try:
            found = _verify(result, settings)
        except scenarios.ScenarioFileError as error:  # a REM @sim line of the program, which the v3 run reads first
            program = paths.get("program") or paths.get("configuration") or ""
            problems += [str(replace(mistake, source=program)) for mistake in error.errors]
            continue
        verified.append(Verified(paths.get("program"), paths.get("configuration"), found))
    return verified, problems


def _verify(result: MigrationResult, settings: Settings) -> Verification:
    if settings.to == "mintmt":
        from mintlang.migrate.mintmt.verification import verify as to_mintmt  # noqa: PLC0415 - loads the simulator

        return to_mintmt(result, controller=settings.controller, scenario=settings.scenario, until_ms=settings.until_ms)
    return verification.verify(
        result,
        v3_controller=settings.v3_controller,
        controller=settings.controller,
        scenario=settings.scenario,
        until_ms=settings.until_ms,
    )


def _whole(files: list[Migrated]) -> MigrationResult | None:
    """An application's migration as ``verify`` takes it: the program's, which holds the configuration's,
    or, for a configuration file alone, that file's under an empty program."""
    results = {item.entry.role: item.entry.result for item in files}
    if "program" in results:
        return results["program"]
    configuration = results.get("configuration")
    if configuration is None:
        return None
    return MigrationResult("", "", (), (), {}, configuration=configuration)


def output(
    verified: list[Verified],
    output_format: str,
    console: Console,
    *,
    quiet: bool,
    problems: list[str],
    to: str = "v4",
) -> None:
    """The report on ``console`` (standard output or ``--output-file``); ``quiet`` leaves out what was not
    verified and the totals. The text report leaves ``problems`` to standard error, where the command
    writes them whatever the format."""
    sides = verification_report.V4_TO_MINTMT if to == "mintmt" else verification_report.V3_TO_V4
    data = verification_report.report(verified, sides, problems)
    if output_format == "json":
        import json  # noqa: PLC0415 - a migration without --verify imports this module too

        console.file.write(json.dumps(data, indent=2, ensure_ascii=False) + "\n")
    else:
        verification_report.render_text(data, console, quiet=quiet, sides=sides)
