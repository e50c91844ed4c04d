"""Load the generated keyword database into the typed records of ``model``.

The JSON is package data; it is read once per process and indexed so that
every lookup the lexer makes is a dictionary hit. ``database.bin`` beside it holds the
same documents marshalled, each with the CRC-32 of the JSON it was made from: a document
whose JSON still has that checksum is taken from it (parsing the JSON was most of loading
the database, and marshal reads the same four times as fast), any other is parsed from
its JSON, so an edited file is never read stale. ``python -m tools.keyworddb`` writes both.
"""

from __future__ import annotations

import binascii
import marshal
import re
from collections.abc import Callable, Iterable, Iterator, Mapping
from dataclasses import field
from enum import StrEnum
from functools import cache, cached_property
from types import MappingProxyType
from typing import Any, TypeVar

from mintlang.allocation import kept_without_collector
from mintlang.dialect import Dialect
from mintlang.keyworddb.model import (
    Addressing,
    Attributes,
    Constant,
    Controller,
    ErrorCode,
    ErrorKind,
    Keyword,
    KeywordKind,
    MigrationClass,
    Rename,
    Spelling,
    V3Constant,
    V3Keyword,
    ValueRange,
)
from mintlang.package_data import read_bytes
from mintlang.records import record

_Record = TypeVar("_Record")
_CHANNEL_GLUED = re.compile(r"^(?P<base>.*?\D)(?P<channel>\d+)$")
DOCUMENTS = (
    "keywords_v4.json",
    "keywords_v3.json",
    "keywords_mintmt.json",
    "renames_v3_to_v4.json",
    "constants_v4.json",
    "constants_v3.json",
    "constants_mintmt.json",
    "errors.json",
    "conflicts.json",
)
COMPACT = "database.bin"
_Member = TypeVar("_Member", bound=StrEnum)


def _by_value(kind: type[_Member]) -> Mapping[str, _Member]:
    """The members of ``kind`` by value: a dict answers about twenty times as fast as calling the enum,
    which loading the database did 1,438 times."""
    return {member.value: member for member in kind}


_KINDS, _ERROR_KINDS = _by_value(KeywordKind), _by_value(ErrorKind)
_ADDRESSINGS, _MIGRATIONS = _by_value(Addressing), _by_value(MigrationClass)
Documents = dict[str, list[dict[str, Any]]]


def compact(texts: Mapping[str, bytes]) -> bytes:
    """What ``database.bin`` holds for the JSON ``texts`` (file name -> bytes): each parsed, with its CRC-32."""
    return marshal.dumps({name: (binascii.crc32(text), _parsed(text)) for name, text in texts.items()})


def compacted(texts: Mapping[str, bytes], copy: bytes) -> Documents:
    """The documents of ``copy`` (what ``compact`` made) whose JSON ``texts`` still has their checksum."""
    try:
        kept = marshal.loads(copy)
    except (ValueError, EOFError, TypeError):
        return {}
    if not isinstance(kept, dict):
        return {}
    return {
        name: kept[name][1] for name, text in texts.items() if name in kept and kept[name][0] == binascii.crc32(text)
    }


def documents() -> Documents:
    """Every document of the database: from ``database.bin`` where it was made from the JSON as it is."""
    texts = {name: read_bytes("mintlang.keyworddb", "data", name) for name in DOCUMENTS}
    try:
        kept = compacted(texts, read_bytes("mintlang.keyworddb", "data", COMPACT))
    except OSError:
        kept = {}
    return {name: kept[name] if name in kept else _parsed(text) for name, text in texts.items()}


def _parsed(text: bytes) -> list[dict[str, Any]]:
    """A JSON document; ``json`` is imported only here, which a start with a current copy never reaches."""
    import json  # noqa: PLC0415

    return json.loads(text.decode("utf-8"))


def _range(raw: dict[str, Any] | None) -> ValueRange | None:
    if raw is None:
        return None
    included = raw.get("minimum_included", True), raw.get("maximum_included", True)
    allowed = tuple(raw["allowed"]) if raw.get("allowed") is not None else None
    return ValueRange(raw["text"], raw["minimum"], raw["maximum"], raw["fractional"], *included, allowed)


@cache
def _controllers(names: tuple[str, ...]) -> tuple[Controller, ...]:
    """The controllers named: the 675 lists of keywords and attribute rows name 18 different sets."""
    return tuple(map(Controller, names))


def _attributes(raw: dict[str, Any]) -> Attributes:
    return Attributes(
        controllers=_controllers(tuple(raw["controllers"])),
        read=raw["read"],
        write=raw["write"],
        command=raw["command"],
        multi_axis=raw["multi_axis"],
        scaled=raw["scaled"],
        default=raw["default"],
        range=_range(raw["range"]),
    )


def _listings(keywords: Mapping[str, Keyword]) -> Mapping[str, tuple[str, ...]]:
    """Each constant's name in upper case, and the keywords listing it, sorted."""
    listed: dict[str, list[str]] = {}
    for keyword in keywords.values():
        for name in keyword.constants:
            listed.setdefault(name.upper(), []).append(keyword.name)
    return MappingProxyType({name: tuple(sorted(owners)) for name, owners in listed.items()})


def _keyword(raw: dict[str, Any]) -> Keyword:
    return Keyword(
        name=raw["name"],
        abbreviations=tuple(raw["abbreviations"]),
        kind=_KINDS[raw["kind"]],
        addressing=_ADDRESSINGS[raw["addressing"]],
        channel_suffix=raw["channel_suffix"],
        parameters=tuple(raw["parameters"]),
        attributes=tuple(_attributes(row) for row in raw["attributes"]),
        controllers=_controllers(tuple(raw["controllers"])),
        formats=tuple(raw["formats"]),
        constants=tuple(raw["constants"]),
        see_also=tuple(raw["see_also"]),
        summary=raw["summary"],
        documented=raw["documented"],
        line=raw["line"],
        notes=tuple(raw["notes"]),
        indices=tuple(raw.get("indices", ())),
        manual=raw.get("manual", "000"),
    )


def _spelling(raw: dict[str, Any]) -> Spelling:
    return Spelling(
        raw["name"],
        tuple(raw["abbreviations"]),
        _KINDS[raw["kind"]],
        bool(raw["parameters"]),
        raw["channel_suffix"],
        len(raw.get("indices", ())),
    )


class _Built(Mapping[str, _Record]):
    """Records by upper-case name, each made from its entry when first asked for and kept: building the
    404 v4 keywords was half of loading the database, and a one-line check reads a few of them."""

    __slots__ = ("_entries", "_made", "_make")

    def __init__(self, entries: Mapping[str, dict[str, Any]], make: Callable[[dict[str, Any]], _Record]) -> None:
        self._entries, self._make = entries, make
        self._made: dict[str, _Record] = {}

    def __getitem__(self, name: str) -> _Record:
        made = self._made.get(name)
        if made is None:
            made = self._made[name] = self._make(self._entries[name])
        return made

    def get(self, name: str, default: Any = None) -> Any:
        return self[name] if name in self._entries else default

    def __contains__(self, name: object) -> bool:
        return name in self._entries

    def __iter__(self) -> Iterator[str]:
        return iter(self._entries)

    def __len__(self) -> int:
        return len(self._entries)


def _constant(raw: dict[str, Any]) -> Constant:
    return Constant(raw["name"], raw["value"], raw["keyword"], raw["line"])


def _v3_keyword(raw: dict[str, Any]) -> V3Keyword:
    return V3Keyword(
        name=raw["name"],
        abbreviations=tuple(raw["abbreviations"]),
        read=raw["read"],
        write=raw["write"],
        command=raw["command"],
        addressing=_ADDRESSINGS[raw["addressing"]],
        function=raw["function"],
        v4_names=tuple(raw["v4_names"]),
        status=raw["status"],
        migration=_MIGRATIONS[raw["migration"]],
        line=raw["line"],
        formats=tuple(raw["formats"]),
    )


def _rename(raw: dict[str, Any]) -> Rename:
    return Rename(raw["old"], raw["old_abbreviation"], tuple(raw["new"]), raw["status"], raw["line"])


def _index(
    records: Iterable[_Record], *keys: Callable[[_Record], Iterable[str]], fixed: Mapping[str, _Record] | None = None
) -> Mapping[str, _Record]:
    """Upper-cased word -> record.  ``fixed`` entries come first, then every name
    before any abbreviation, each in record order; the first claim wins."""
    index: dict[str, _Record] = dict(fixed or {})
    records = list(records)
    for key in keys:
        for entry in records:
            for word in key(entry):
                index.setdefault(word.upper(), entry)
    return MappingProxyType(index)


@record(slots=False)
class KeywordDatabase:
    """Everything the manuals say about keywords, constants and errors, indexed for lookup.

    What a check of Mint v4 reads is indexed when the database is loaded: v4's constants, and every v4
    keyword's spellings, whose records are each built when first asked for (the lexer reads the spellings
    through ``owner`` and ``spellings_of``). The rest (v3's keywords, constants and renames, MintMT's own
    words, the errors) is built from its documents when first asked for, which a one-line v4 check never does.
    """

    keywords: Mapping[str, Keyword]  # each built when first asked for
    constants: Mapping[str, Constant]
    _words: Mapping[str, str] = field(repr=False)  # spelling -> the name of the keyword it stands for
    _shared: Mapping[str, tuple[str, ...]] = field(repr=False)  # abbreviation -> the keywords it is given to
    _entries: Mapping[str, dict[str, Any]] = field(repr=False, compare=False)  # v4's keyword entries by name
    _later: Documents = field(repr=False, compare=False)  # the documents of what is built when first asked for

    @cached_property
    def errors(self) -> Mapping[int, ErrorCode]:
        made = (
            ErrorCode(r["code"], _ERROR_KINDS[r["kind"]], r["title"], r["constant"], r["line"])
            for r in self._later["errors.json"]
        )
        return MappingProxyType({error.code: error for error in made})

    @cached_property
    def v3_keywords(self) -> Mapping[str, V3Keyword]:
        return _by_name(self._v3_records, lambda k: k.name)

    @cached_property
    def v3_one_value_writes(self) -> frozenset[str]:
        """The v3 keywords a write gives one value (``OUT.1 = 1, 0`` is "Missing parameter"): those addressed by
        no axis whose v4 keyword is held to one (``Keyword.one_value_a_write``). Their v3 formats write one
        ``<expr>`` (OUT 001:10519, OUT0..OUT7 10611-10618, AUXDAC 5929, BAUD 6100, ENABLE 7555), and a value
        with no place to go is "Missing parameter" (001:990-992, 13097-13109), which the guide words for axes
        only; XIO, whose format writes a list (001:12731), has no v4 keyword and is not among them."""
        return frozenset(
            name
            for name, record in self.v3_keywords.items()
            if record.write
            and record.addressing is not Addressing.AXIS
            and any((v4 := self.keywords.get(new)) is not None and v4.one_value_a_write for new in record.v4_names)
        )

    @cached_property
    def _v3_records(self) -> list[V3Keyword]:
        return [_v3_keyword(raw) for raw in self._later["keywords_v3.json"]]

    @cached_property
    def v3_constants(self) -> Mapping[str, V3Constant]:
        read = self._later["constants_v3.json"]
        return _by_name((V3Constant(r["name"], r["value"], r["v4_name"], r["line"]) for r in read), lambda c: c.name)

    @cached_property
    def renames(self) -> tuple[Rename, ...]:
        return tuple(_rename(raw) for raw in self._later["renames_v3_to_v4.json"])

    @cached_property
    def mintmt_keywords(self) -> Mapping[str, Keyword]:
        """MintMT's own keywords, and v4 ones MintMT addresses otherwise."""
        return MappingProxyType({name: _keyword(raw) for name, raw in self._mintmt_entries.items()})

    @cached_property
    def _mintmt_entries(self) -> Mapping[str, dict[str, Any]]:
        """MintMT's keyword entries by name. One that replaces a v4 keyword keeps that keyword's abbreviations:
        the notes write none, and what they do not show is v4's (mintlang/MINTMT.md, MT-1)."""
        made: dict[str, dict[str, Any]] = {}
        for raw in self._later["keywords_mintmt.json"]:
            name = raw["name"].upper()
            v4 = self._entries.get(name)
            made[name] = {**raw, "abbreviations": v4["abbreviations"]} if v4 and not raw["abbreviations"] else raw
        return MappingProxyType(made)

    @cached_property
    def mintmt_constants(self) -> Mapping[str, Constant]:
        return _by_name(map(_constant, self._later["constants_mintmt.json"]), lambda c: c.name)

    @cached_property
    def _v3_words(self) -> Mapping[str, V3Keyword]:
        return _index(self._v3_records, lambda k: (k.name,), lambda k: k.abbreviations)

    @cached_property
    def _old_words(self) -> Mapping[str, Rename]:
        return _index(self.renames, lambda r: (r.old,), lambda r: (r.old_abbreviation,) if r.old_abbreviation else ())

    def lookup(self, word: str, controller: Controller | None = None) -> Keyword | None:
        """The v4 keyword ``word`` names or abbreviates, in any case: see ``owner``."""
        name = self.owner(word, controller)
        return None if name is None else self.keywords[name]

    def owner(self, word: str, controller: Controller | None = None) -> str | None:
        """The name of the v4 keyword ``word`` names or abbreviates, in any case.

        A channel glued to a keyword that allows it (``IN3``, ``#FASTIN2``)
        resolves to that keyword. An abbreviation the guide gives to two
        keywords names, on ``controller``, the only one of them that controller
        has (HP is HOMEPOS on a NextMove, HANDLERPENDING on a MintDrive);
        otherwise, or without a controller, the one conflicts.json resolved it to.
        """
        upper = word.upper()
        if controller is not None and (shared := self._shared.get(upper)) is not None:
            # Read from the entries: the lexer asks of every abbreviation, and needs no record built.
            available = [name for name in shared if controller in self._entries[name]["controllers"]]
            if len(available) == 1:
                return available[0]
        if (found := self._words.get(upper)) is not None:
            return found
        match = _CHANNEL_GLUED.match(upper)
        if match and (base := self._words.get(match["base"])) is not None and self._entries[base]["channel_suffix"]:
            return base
        return None

    def spellings_of(self, dialect: Dialect) -> list[Spelling]:
        """How each keyword of a v4-based dialect is written, in the order of ``keywords_of``."""
        entries = self._entries
        if dialect is Dialect.MINTMT:
            entries = {**entries, **self._mintmt_entries}
        return [_spelling(raw) for raw in entries.values()]

    def keywords_of(self, dialect: Dialect) -> Mapping[str, Keyword]:
        """The keywords of a v4-based dialect by name: v4's, with MintMT's own over them in MintMT."""
        return self._mintmt_all_keywords if dialect is Dialect.MINTMT else self.keywords

    def constants_of(self, dialect: Dialect) -> Mapping[str, Constant]:
        """The predefined constants of a v4-based dialect by name."""
        return self._mintmt_all_constants if dialect is Dialect.MINTMT else self.constants

    def listing(self, constant: str, dialect: Dialect) -> tuple[str, ...]:
        """The keywords of a v4-based dialect whose entries list ``constant`` among their values, by name: one
        constant may be the value of several (``_emCRASH_STOP`` of LIMITMODE, 000:13486, and of SOFTLIMITMODE,
        000:16050), so its record's one ``keyword`` does not say all of them."""
        listings = self._mintmt_listings if dialect is Dialect.MINTMT else self._v4_listings
        return listings.get(constant.upper(), ())

    @cached_property
    def _v4_listings(self) -> Mapping[str, tuple[str, ...]]:
        return _listings(self.keywords)

    @cached_property
    def _mintmt_listings(self) -> Mapping[str, tuple[str, ...]]:
        return _listings(self._mintmt_all_keywords)

    @cached_property
    def _mintmt_all_keywords(self) -> Mapping[str, Keyword]:
        return MappingProxyType({**self.keywords, **self.mintmt_keywords})

    @cached_property
    def _mintmt_all_constants(self) -> Mapping[str, Constant]:
        return MappingProxyType({**self.constants, **self.mintmt_constants})

    def lookup_v3(self, word: str) -> V3Keyword | None:
        """The v3 keyword ``word`` names or abbreviates, in any case."""
        return self._v3_words.get(word.upper())

    def rename_of(self, word: str) -> Rename | None:
        """The rename record of an old v3 name or abbreviation the v4 guide retires."""
        return self._old_words.get(word.upper())


def _by_name(records: Iterable[_Record], name: Callable[[_Record], str]) -> Mapping[str, _Record]:
    return MappingProxyType({name(record).upper(): record for record in records})


def _abbreviation_conflicts(conflicts: list[dict[str, Any]]) -> list[dict[str, Any]]:
    return [conflict for conflict in conflicts if conflict["kind"] == "abbreviation"]


def _abbreviation_choices(conflicts: list[dict[str, Any]]) -> dict[str, str]:
    """The generator's resolution of abbreviations the guide gives to two keywords."""
    return {conflict["subject"].upper(): conflict["resolved_to"].upper() for conflict in conflicts}


def _shared_abbreviations(conflicts: list[dict[str, Any]]) -> Mapping[str, tuple[str, ...]]:
    """Each abbreviation the guide gives to two keywords, with both."""
    return MappingProxyType(
        {conflict["subject"].upper(): tuple(name.upper() for name in conflict["keywords"]) for conflict in conflicts}
    )


@cache
@kept_without_collector  # nine collections of a tiny mint-run walked the documents as they were read
def database() -> KeywordDatabase:
    """The database shipped with the package, loaded once per process."""
    read = documents()
    entries = {raw["name"].upper(): raw for raw in read["keywords_v4.json"]}
    constants = [_constant(raw) for raw in read["constants_v4.json"]]
    conflicts = _abbreviation_conflicts(read["conflicts.json"])
    preferred = sorted(entries, key=lambda name: (not entries[name]["documented"], entries[name]["line"]))
    return KeywordDatabase(
        keywords=_Built(entries, _keyword),
        constants=_by_name(constants, lambda c: c.name),
        _words=_index(
            preferred,
            lambda name: (name,),
            lambda name: entries[name]["abbreviations"],
            fixed=_abbreviation_choices(conflicts),
        ),
        _shared=_shared_abbreviations(conflicts),
        _entries=MappingProxyType(entries),
        _later={name: read[name] for name in _BUILT_WHEN_ASKED},
    )


# The documents of what ``KeywordDatabase`` builds when first asked for.
_BUILT_WHEN_ASKED = (
    "errors.json",
    "keywords_v3.json",
    "constants_v3.json",
    "renames_v3_to_v4.json",
    "keywords_mintmt.json",
    "constants_mintmt.json",
)
