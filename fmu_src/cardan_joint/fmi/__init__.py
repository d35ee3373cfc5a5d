"""The pythonfmu and pythonfmu3 side: the slave classes and their model descriptions."""
