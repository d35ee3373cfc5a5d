"""The pythonfmu side: the slave class and its model description."""
