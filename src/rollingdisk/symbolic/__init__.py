"""Symbolic derivation of the equations of motion (sympy) and the check of the paper.

Outside the numeric core: nothing in the core imports this package.
"""
