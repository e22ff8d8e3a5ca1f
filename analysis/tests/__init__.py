"""Unit tests of polydecomp_analysis and its scripts; `python3 -m unittest discover -s analysis -p
"test_*.py"` runs them (ctest's analysis test)."""
