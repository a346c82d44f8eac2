"""The exceptions of superpack, one per exit code of the command line (README, "The command line")."""


class Error(Exception):
    """A superpack call that gave no result. `result` is the command's document, typed, when it
    printed one (an undecided answer keeps what it did decide), else None."""

    def __init__(self, message, result=None):
        super().__init__(message)
        self.result = result


class InputError(Error, ValueError):
    """Bad input (exit 2): a value out of range, a file that cannot be read or written."""


class Impossible(Error):
    """A certified impossibility (exit 3): what was asked provably does not exist."""


class Undecided(Error):
    """Undecided at this precision (exit 4): try more digits or a finer setting."""


class InvalidCertificate(Error):
    """The checker rejects the certificate (exit 1), at the path the message names."""


class InternalError(Error, RuntimeError):
    """A bug in superpack (exit 5): please report it with the call that raised it."""


BY_EXIT_CODE = {1: InvalidCertificate, 2: InputError, 3: Impossible, 4: Undecided, 5: InternalError}
