"""The errors tumble raises: a scene it refuses, a simulation that blew up, a render that failed."""

import re

# "FILE:LINE:COL: KEY: message" (a key is a dotted path such as bodies[0].mass), or
# "FILE:LINE:COL: message" (a TOML syntax error), or "FILE: message" (a file that cannot be read).
_LOCATED = re.compile(r"^(?P<file>.+?):(?P<line>\d+):(?P<column>\d+): (?P<rest>.*)$", re.S)
_KEY = re.compile(r"^(?P<key>[A-Za-z_][\w]*(?:\[\d+\])?(?:\.[A-Za-z_][\w]*(?:\[\d+\])?)*): ")


class SceneError(ValueError):
    """A scene tumble refuses, with the same message as the command line's.

    Attributes: ``file``, ``line`` and ``column`` (1-based; None when the error has no place in
    the file, such as a file that does not exist), ``key`` (the dotted key, such as
    ``bodies[0].mass``, or None) and ``message`` (the whole text)."""

    def __init__(self, message):
        super().__init__(message)
        self.message = message
        self.file = self.line = self.column = self.key = None
        located = _LOCATED.match(message)
        if located:
            self.file = located["file"]
            self.line = int(located["line"])
            self.column = int(located["column"])
            key = _KEY.match(located["rest"])
            if key:
                self.key = key["key"]
        elif ": " in message:
            self.file = message.split(": ", 1)[0]


class SimulationError(RuntimeError):
    """A simulation that blew up (a state that is no longer finite), with the CLI's message."""


class RenderError(RuntimeError):
    """A render that failed (a full disk, a missing font); the output folder was left as it was."""
