"""The package's exception."""


class HandspringError(Exception):
    """A failure the C library reported: `message` is its text (`file:line: what is wrong` for a
    scenario file), `status` the hs_status code where the call returned one (else None)."""

    def __init__(self, message, status=None):
        super().__init__(message)
        self.message = message
        self.status = status
