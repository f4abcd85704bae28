"""Base of the scene records: frozen dataclasses whose vector fields are read-only arrays."""

from __future__ import annotations

import dataclasses

import numpy as np


class Record:
    """Mixin giving frozen dataclasses value equality that also compares array fields."""

    __hash__ = None  # array fields are not hashable; equality is by value

    def __eq__(self, other: object) -> bool:
        if type(other) is not type(self):
            return NotImplemented
        return all(
            np.array_equal(getattr(self, f.name), getattr(other, f.name))
            if isinstance(getattr(self, f.name), np.ndarray)
            else getattr(self, f.name) == getattr(other, f.name)
            for f in dataclasses.fields(self)
            if f.compare
        )

    def _set(self, **values: object) -> None:
        """Store validated values on a frozen instance (used by ``__post_init__`` only).

        Straight into the instance's dict, as ``object.__setattr__`` would put them (the
        fields are plain attributes), at half its cost.
        """
        self.__dict__.update(values)
