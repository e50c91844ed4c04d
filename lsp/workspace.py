"""Per-document analyses, cached by version, with the paired configuration file.

Every feature reads a ``Snapshot``: the text of one version, the core's
semantic model and diagnostics for it, and how to turn its offsets into LSP
positions. A snapshot is computed at most once per (version, partner text,
settings), so hover and completion after a check cost no re-analysis.
"""

from __future__ import annotations

import functools
import logging
from collections.abc import Callable, Collection, Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path
from urllib.parse import quote, unquote

from pygls.uris import from_fs_path, to_fs_path

import mintlang
from mintlang.allocation import collector_paused
from mintlang.codes import selector
from mintlang.detection import detect_dialect, detect_dialect_after
from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.keyworddb.model import Controller, Keyword
from mintlang.lsp.collector import Collector
from mintlang.lsp.positions import Positions
from mintlang.pairing import DEFAULT_PATTERN, Pairing, is_program, listed_as, names_in
from mintlang.records import record
from mintlang.semantic.model import SemanticModel
from mintlang.semantic.units import Unit
from mintlang.settings import FileSettings, SettingsError, settings_for
from mintlang.syntax.parser import Document
from mintlang.syntax.vocabulary import Vocabulary, vocabulary

log = logging.getLogger(__name__)

AUTO = "auto"  # mint.dialect's value asking for the dialect to be detected from each program's text
MAX_CHARACTERS = 5_000_000  # larger files are not analysed (about 220,000 lines: 3 s to open, 0.5 s a name edit)


@record
class Settings:
    """The ``mint.*`` settings; ``configPairing`` names the configuration file of ``<name>.mnt``.

    A document's settings are those of its settings file (``mint.toml`` or
    ``[tool.mint]``, see ``mintlang.settings``) with the editor's over them:
    ``given`` names the settings the editor sent, which win over the file's.
    ``mint.dialect = "auto"`` sets ``dialect_from_text``: each program's dialect
    is then detected from its text (``mintlang.detection``), ``dialect`` (v4)
    standing for a text not at hand.
    """

    controller: Controller = Controller.NEXTMOVE_PCI
    dialect: Dialect = Dialect.V4
    dialect_from_text: bool = False
    config_pairing: str = DEFAULT_PATTERN
    debounce_ms: int = 150
    select: tuple[str, ...] | None = None  # codes or prefixes; None: the errors and warnings, not the hints
    ignore: tuple[str, ...] = ()
    config_file: Path | None = None  # the configuration file of every program (the settings file's ``config``)
    rules_url: str | None = None  # where the rule pages are, a folder or a {code} template; None: the project's
    given: frozenset[str] = frozenset()

    @property
    def words(self) -> Vocabulary:
        """How keywords are spelt in the dialect, an abbreviation two keywords share naming the controller's one."""
        return vocabulary(self.dialect, self.controller)

    def keyword(self, spelling: str) -> Keyword | None:
        """The record of the keyword ``spelling`` names in the dialect (MintMT's own entry over v4's)."""
        name = self.words.keyword_name(spelling) or spelling
        return database().keywords_of(self.dialect).get(name.upper()) or database().lookup(name)

    def check(self, program: str, config: str | None, previous: mintlang.Analysis | None = None) -> mintlang.Analysis:
        """The check of a program (and its configuration file) under these settings; ``previous``, the analysis
        of an earlier version, re-reads only what changed."""
        return mintlang.check_application(
            program,
            dialect=self.dialect,
            controller=self.controller,
            config=config,
            select=self.select,
            ignore=self.ignore,
            previous=previous,
        )

    @classmethod
    def from_options(cls, options: object, base: Settings | None = None) -> Settings:
        """Settings from ``initializationOptions`` or a configuration answer over ``base``: a setting left out
        keeps ``base``'s value, a bad value too; ``null`` (set nowhere in the editor) is the default, which the
        settings file's value overrides."""
        base = base or cls()
        if isinstance(options, Mapping) and isinstance(options.get("mint"), Mapping):
            options = options["mint"]
        if not isinstance(options, Mapping):
            return base
        values = {
            "controller": base.controller,
            "dialect": base.dialect,
            "config_pairing": base.config_pairing,
            "debounce_ms": base.debounce_ms,
            "select": base.select,
            "ignore": base.ignore,
            "rules_url": base.rules_url,
        }
        given = set(base.given)
        from_text = base.dialect_from_text
        if options.get("dialect") == AUTO:
            from_text = True
            given.add("dialect")
            options = {key: value for key, value in options.items() if key != "dialect"}
        for key, name, convert in (
            ("controller", "controller", Controller),
            ("dialect", "dialect", Dialect),
            ("configPairing", "config_pairing", _pairing_pattern),
            ("debounceMs", "debounce_ms", _milliseconds),
            ("select", "select", _codes),
            ("ignore", "ignore", _codes),
            ("rulesUrl", "rules_url", _text),
        ):
            if key not in options:
                continue
            if options[key] is None:  # not set in the editor: the default, under the settings file's
                values[name] = getattr(_DEFAULTS, name)
                given.discard(name)
            else:
                try:
                    values[name] = convert(options[key])
                    given.add(name)
                except (ValueError, TypeError):
                    log.warning("ignoring setting mint.%s = %r", key, options[key])
                    continue
            from_text = from_text and name != "dialect"
        return cls(**values, dialect_from_text=from_text, given=frozenset(given))

    def for_text(self, program: str, detect: Callable[[str], Dialect] | None = None) -> Settings:
        """These settings for a program whose text is ``program``: its dialect detected if the editor asks
        (by ``detect``, one that remembers the last text it read)."""
        return replace(self, dialect=(detect or _detected)(program)) if self.dialect_from_text else self

    def over(self, project: FileSettings) -> Settings:
        """These settings over a settings file's: each the editor sent wins; both ignore lists apply."""
        from_file: dict[str, object] = {
            "controller": project.controller.value,
            "dialect": project.dialect.value,
            "config_pairing": project.config_pairing.value or "",
            "select": project.selected,
        }
        kept = {name: value for name, value in from_file.items() if name not in self.given}
        return replace(self, **kept, ignore=(*project.ignored, *self.ignore), config_file=project.config.value)


_DEFAULTS = Settings()


@record
class File:
    uri: str
    positions: Positions


@record
class Snapshot:
    """One analysed version of a document (program or configuration file)."""

    uri: str
    version: int | None
    unit: Unit
    analysis: mintlang.Analysis  # of both files: the next version's check starts from it
    diagnostics: tuple[mintlang.Diagnostic, ...]
    files: Mapping[Unit, File]
    settings: Settings
    skipped: str | None = None  # why the text was not analysed (binary, too large)

    @property
    def model(self) -> SemanticModel:
        return self.analysis.model

    @property
    def document(self) -> Document:
        return self.model.document(self.unit)

    @property
    def positions(self) -> Positions:
        return self.files[self.unit].positions


TextReader = Callable[[str], str | None]  # uri -> text of an open document or file on disk, if any


# Every request reads its snapshot's settings: the dialect of the last few texts is kept, not detected each time.
_detected = functools.lru_cache(maxsize=16)(detect_dialect)


def _codes(value: object) -> tuple[str, ...]:
    """Codes or prefixes, listed (``["E", "I201"]``) or comma-separated (``"E,I201"``), read as --select reads them."""
    items = value.split(",") if isinstance(value, str) else value
    if not isinstance(items, list | tuple) or not all(isinstance(item, str) for item in items):
        raise TypeError("a list of codes")
    return tuple(selector(item) for item in items if item.strip())


def _milliseconds(value: object) -> int:
    """A whole number of milliseconds, 0 or more, as the extension's schema says: ``true`` or ``-5`` is refused,
    not read as 1 ms or a negative wait, and ``1.5`` is not cut to 1."""
    if isinstance(value, bool) or not isinstance(value, int | float) or value < 0 or not float(value).is_integer():
        raise ValueError("a whole number of milliseconds")
    return int(value)


def _text(value: object) -> str:
    """A string setting: a list or a number is refused rather than written out as ``['x']`` or ``5``."""
    if not isinstance(value, str):
        raise TypeError("a string")
    return value


def _pairing_pattern(value: object) -> str:
    """A configuration file name with ``<name>`` for the program's (see ``mintlang.pairing``)."""
    pattern = _text(value)
    Pairing.from_pattern(pattern)  # a ValueError for a folder keeps the setting as it was
    return pattern


def partner(uri: str, settings: Settings, opened: Collection[str] = ()) -> tuple[Unit, str | None]:
    """Which file ``uri`` is, and the URI of the other file of its application (the core's pairing rule).

    The other URI is ``uri`` with its last segment replaced, so it is written as the
    client writes URIs (VS Code sends ``file:///c%3A/...`` where a path round trip
    would give ``file:///c:/...``, and the two would name different documents).
    ``opened`` are the URIs of the documents open in the editor: one may not be on disk yet.
    """
    folder, slash, segment = uri.rpartition("/")
    if settings.config_file is not None and is_program(unquote(segment)):
        return Unit.PROGRAM, from_fs_path(str(settings.config_file))
    pairing = Pairing.from_pattern(settings.config_pairing)
    if not slash or pairing is None:
        return Unit.PROGRAM, None
    unit, other = pairing.partner_name(unquote(segment))
    return unit, None if other is None else _sibling(folder, other, opened)


def _sibling(folder: str, name: str, opened: Collection[str]) -> str:
    """The URI of ``name`` in the folder URI ``folder``, matched without regard to case as on the
    controller's PC (APP.MNT, app.cfg): among the open documents first, then on disk."""
    exact = f"{folder}/{quote(name)}"
    if exact in opened:
        return exact
    beside: dict[str, str] = {}
    for uri in opened:
        other_folder, _, segment = uri.rpartition("/")
        if other_folder == folder:
            beside.setdefault(unquote(segment), uri)
    listed = listed_as(name, beside)
    if listed is not None:
        return beside[listed]
    path = to_fs_path(exact)
    listed = listed_as(name, names_in(Path(path).parent)) if path is not None else None
    return exact if listed is None else f"{folder}/{quote(listed)}"


def _unreadable(text: str) -> str | None:
    if "\x00" in text:
        return "binary file: not analysed"
    if len(text) > MAX_CHARACTERS:
        return f"file larger than {MAX_CHARACTERS} characters: not analysed"
    return None


@dataclass
class Analyses:
    """The cache of snapshots, one per open document."""

    read: TextReader
    opened: Callable[[], Collection[str]] = tuple  # the URIs of the documents open in the editor
    settings: Settings = field(default_factory=Settings)
    encoding: str = "utf-16"  # the position encoding negotiated with the client
    collector: Collector | None = None  # told of each new snapshot, to keep it out of the collector's scans
    _cache: dict[str, tuple[tuple[object, ...], Snapshot]] = field(default_factory=dict)
    _reported: set[str] = field(default_factory=set)  # settings file problems already logged
    _last_detected: tuple[str, Dialect] | None = None  # the last program text whose dialect was detected

    def _detect(self, program: str) -> Dialect:
        """The dialect of ``program``, reading only what changed since the last text detected."""
        last = self._last_detected
        dialect = detect_dialect_after(*last, program) if last is not None else detect_dialect(program)
        self._last_detected = (program, dialect)
        return dialect

    def settings_for(self, uri: str) -> Settings:
        """The editor's settings over those of the document's settings file, if it is a file that has one.

        A settings file that cannot be used is logged, once while it stays so, and the editor's settings apply.
        """
        path = to_fs_path(uri) if uri.startswith("file:") else None
        if path is None:
            return self.settings
        try:
            return self.settings.over(settings_for(Path(path)))
        except SettingsError as error:
            if str(error) not in self._reported:
                self._reported.add(str(error))
                log.warning("settings file not used: %s", error)
            return self.settings

    def snapshot(self, uri: str, text: str, version: int | None) -> Snapshot:
        """The analysis of ``text``, reused while neither it, its partner nor the settings change."""
        settings = self.settings_for(uri)
        unit, other = partner(uri, settings, self.opened())
        other_text = self.read(other) if other is not None else None
        settings = settings.for_text(text if unit is Unit.PROGRAM else other_text or "", self._detect)
        key = (version, text, other_text, settings, self.encoding)
        cached = self._cache.get(uri)
        if cached is not None and cached[0] == key:
            return cached[1]
        with collector_paused():  # frozen before the collector runs again, which then has nothing new to scan
            snapshot = self._analyse(
                uri, text, version, unit=unit, other=other, other_text=other_text, settings=settings
            )
            self._cache[uri] = (key, snapshot)
            if self.collector is not None:
                self.collector.analysed()
        return snapshot

    def latest(self, uri: str) -> Snapshot | None:
        """The last snapshot of ``uri`` whatever its version."""
        cached = self._cache.get(uri)
        return cached[1] if cached is not None else None

    def forget(self, uri: str) -> None:
        self._cache.pop(uri, None)

    def _analyse(
        self,
        uri: str,
        text: str,
        version: int | None,
        *,
        unit: Unit,
        other: str | None,
        other_text: str | None,
        settings: Settings,
    ) -> Snapshot:
        skipped = _unreadable(text)
        if other_text is not None and _unreadable(other_text):
            other_text = None
        mine = "" if skipped else text
        if unit is Unit.CONFIGURATION:
            program, config = other_text or "", mine
        else:
            program, config = mine, other_text
        before = self._cache.get(uri)
        # a keystroke re-reads what it touched
        analysis = settings.check(program, config, before[1].analysis if before is not None else None)
        analysed = analysis.model.document(unit) if not skipped else None
        files = {unit: File(uri, Positions(text, self.encoding, analysed.line_index if analysed else None))}
        if other is not None and other_text is not None:
            other_unit = Unit.PROGRAM if unit is Unit.CONFIGURATION else Unit.CONFIGURATION
            index = analysis.model.document(other_unit).line_index  # the documents know their lines
            files[other_unit] = File(other, Positions(other_text, self.encoding, index))
        own = analysis.configuration if unit is Unit.CONFIGURATION else analysis.program
        return Snapshot(uri, version, unit, analysis, own, files, settings, skipped)
