"""Tables returned by rastrace: a dict of numpy columns that pandas.DataFrame takes as is."""


class Columns(dict):
    """Column name -> numpy array, keyed like the JSON output of the command line.

    ``title`` and ``parameters`` (the settings the table states: trace, scene, seed, ...) ride
    along as attributes; ``pandas.DataFrame(columns)`` builds the frame without copying text.
    """

    def __init__(self, columns, title="", parameters=None):
        super().__init__(columns)
        self.title = title
        self.parameters = dict(parameters or {})

    def to_pandas(self):
        """A pandas.DataFrame over these arrays without copying them (``copy=False``: pandas then
        keeps one block per column instead of copying them into one 2-D block per dtype)."""
        import pandas

        return pandas.DataFrame(self, copy=False)

    @property
    def rows(self):
        """Number of rows."""
        for column in self.values():
            return len(column)
        return 0

    def __repr__(self):
        return f"Columns({self.title!r}, {self.rows} rows, columns={list(self.keys())})"
