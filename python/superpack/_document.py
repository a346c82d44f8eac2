"""A command's JSON document as Python values: every enclosure an Enclosure, every object a Record."""
from ._enclosure import Enclosure

_ENCLOSURE_KEYS = {"lo", "hi", "lo_exact", "hi_exact", "decimal"}


def _is_enclosure(entry):
    return ("lo" in entry and "hi" in entry and set(entry) <= _ENCLOSURE_KEYS
            and all(isinstance(value, str) for value in entry.values()))


def typed(value):
    """The Python value of a JSON value: {"lo", "hi", ...} -> Enclosure, other objects -> Record,
    lists element by element, the rest as it is (exact texts such as p_exact stay str)."""
    if isinstance(value, dict):
        return Enclosure.from_json(value) if _is_enclosure(value) else Record(value)
    if isinstance(value, list):
        return [typed(element) for element in value]
    return value


def plain(value):
    """The JSON value back: what to_dict() returns, equal to the command's document."""
    if isinstance(value, (Record, Enclosure)):
        return value.to_dict()
    if isinstance(value, list):
        return [plain(element) for element in value]
    return value


class Record:
    """An object of a document: its keys as attributes (record.packing, with '-' read as '_')
    and as items (record["packing"]), read only."""

    _summary = ()

    def __init__(self, document):
        object.__setattr__(self, "_fields", {key: typed(value) for key, value in document.items()})

    def __getattr__(self, name):
        fields = object.__getattribute__(self, "_fields")
        for key in (name, name.replace("_", "-")):
            if key in fields:
                return fields[key]
        raise AttributeError(f"{type(self).__name__} has no field {name!r} (fields: {', '.join(fields)})")

    def __setattr__(self, name, value):
        raise AttributeError(f"{type(self).__name__} is read only")

    def __getitem__(self, key):
        return self._fields[key]

    def __contains__(self, key):
        return key in self._fields

    def keys(self):
        return self._fields.keys()

    def get(self, key, default=None):
        return self._fields.get(key, default)

    def to_dict(self):
        """The JSON document (or object) this was read from, as plain dicts, lists and str."""
        return {key: plain(value) for key, value in self._fields.items()}

    def __eq__(self, other):
        return isinstance(other, Record) and type(self) is type(other) and self._fields == other._fields

    __hash__ = None

    def __dir__(self):
        return sorted(set(super().__dir__()) | {key.replace("-", "_") for key in self._fields})

    def __repr__(self):
        keys = [key for key in self._summary if key in self._fields] or list(self._fields)[:6]
        shown = ", ".join(f"{key}={self._fields[key]!r}" for key in keys)
        more = "" if len(keys) == len(self._fields) else ", ..."
        return f"{type(self).__name__}({shown}{more})"
