"""A test class's fixture of the synthetic sweep (synthetic.py), written and loaded once per class."""

import os
import tempfile
import unittest

from polydecomp_analysis import bounds, results

from . import synthetic


class SyntheticCase(unittest.TestCase):
    """Sets on the class: tmp (the folder the sweep is written to, removed after the class), results_path,
    registry_path, registry, context and runs."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.results_path = os.path.join(cls.tmp.name, "synthetic.json")
        cls.registry_path = os.path.join(cls.tmp.name, "registry.json")
        synthetic.write(cls.results_path, cls.registry_path)
        cls.registry = bounds.load_registry(registry_file=cls.registry_path)
        cls.context, cls.runs = results.load(cls.results_path)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()
