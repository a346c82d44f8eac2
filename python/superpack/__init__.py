"""superpack: certified enclosures for dense superball and superdisk packings, from Python.

Every real number is an Enclosure with exact Fraction ends; p and basis entries are exact (a
str such as '3/2' or '1.15', an int, a Fraction or a Decimal; a float is refused). Each function
runs the command of the same name (README, "The command line") in this process and returns its
JSON document as a typed result. Errors: InputError (a ValueError) for bad input, Impossible,
Undecided, InvalidCertificate. A long call releases the GIL and passes each progress line to
`progress` when given.
"""
from ._commands import (Audit, Best, Critical, Crossover, Density, LatticeCheck, MolecularDynamics, Report,
                        Simulation, Slopes, Superdisk, Verification, audit, best, check_lattice, critical, crossover,
                        density, md, report, simulate, slopes, superdisk, verify)
from ._document import Record
from ._enclosure import Enclosure
from ._errors import Error, Impossible, InputError, InternalError, InvalidCertificate, Undecided

__all__ = ["Audit", "Best", "Critical", "Crossover", "Density", "Enclosure", "Error", "Impossible", "InputError",
           "InternalError", "InvalidCertificate", "LatticeCheck", "MolecularDynamics", "Record", "Report", "Simulation",
           "Slopes", "Superdisk", "Undecided", "Verification", "audit", "best", "check_lattice", "critical",
           "crossover", "density", "md", "report", "simulate", "slopes", "superdisk", "verify"]
