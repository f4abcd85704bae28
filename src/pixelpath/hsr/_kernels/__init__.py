"""Compiled kernels of the hidden-surface methods, one module per method."""
