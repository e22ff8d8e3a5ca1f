"""Claimed bounds from the registry, as functions.

Time bounds ("n*r^2", "n+min(n*r^2,r^4)", "n*log*(n)", ...) use the grammar of core/bound_expr.h:
numbers, n, r, + - * / ^, parentheses, log(x), log^k(x), log*(x), min(...), max(...), sqrt(x). In
cost mode, as in the harness, every factor is kept at least 1 (n >= 2, r >= 1, log2 >= 1), because a
cost is compared as a ratio.

Piece bounds ("== n-2", "== n+2*h-2", "<= 4*OPT", ">= ceil(r/2)+1") are a relation and an expression
over n, r, h (the number of holes) and OPT, with ceil(x) and floor(x) too, evaluated exactly (no
clamping).

A text outside the grammar parses to None: no claim. tests/data/bound_expr_vectors.json holds the time
bounds this parser and core/bound_expr.h are both tested on.
"""

import math
import operator
import re

_TOKEN = re.compile(r"\s*(?:(\d+(?:\.\d*)?|\.\d+)|(log\*|log|min|max|sqrt|ceil|floor|OPT|n|r|h)|(.))")
_RELATIONS = ("==", "<=", ">=", "<", ">")
_BINARY = {"+": operator.add, "-": operator.sub, "*": operator.mul, "/": operator.truediv, "^": operator.pow}


class _Fail(Exception):
    pass


def _tokens(text):
    out = []
    pos = 0
    text = text.strip()
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if not m or m.end() == pos:
            raise _Fail()
        pos = m.end()
        if m.group(1):
            out.append(("num", float(m.group(1))))
        elif m.group(2):
            out.append(("id", m.group(2)))
        else:
            out.append(("op", m.group(3)))
    return out


class _Parser:
    """Recursive descent to a tree of tuples: ("num", v), ("var", name), ("op", sym, a, b),
    ("call", name, [args], power)."""

    def __init__(self, tokens, variables):
        self.t = tokens
        self.i = 0
        self.variables = variables

    def peek(self, kind=None, value=None):
        if self.i >= len(self.t):
            return False
        k, v = self.t[self.i]
        return (kind is None or k == kind) and (value is None or v == value)

    def take(self, kind, value=None):
        if self.peek(kind, value):
            self.i += 1
            return self.t[self.i - 1][1]
        return None

    def expect(self, kind, value=None):
        v = self.take(kind, value)
        if v is None:
            raise _Fail()
        return v

    def whole(self):
        tree = self.sum()
        if self.i != len(self.t):
            raise _Fail()
        return tree

    def sum(self):
        tree = self.product()
        while self.peek("op", "+") or self.peek("op", "-"):
            tree = ("op", self.expect("op"), tree, self.product())
        return tree

    def product(self):
        tree = self.power()
        while self.peek("op", "*") or self.peek("op", "/"):
            tree = ("op", self.expect("op"), tree, self.power())
        return tree

    def power(self):
        tree = self.atom()
        if self.take("op", "^") is not None:
            tree = ("op", "^", tree, self.atom())
        return tree

    def atom(self):
        if self.take("op", "(") is not None:
            tree = self.sum()
            self.expect("op", ")")
            return tree
        number = self.take("num")
        if number is not None:
            return ("num", number)
        name = self.expect("id")
        if name in self.variables:
            return ("var", name)
        if name not in ("log", "log*", "min", "max", "sqrt", "ceil", "floor"):
            raise _Fail()
        power = 1.0
        if name == "log" and self.take("op", "^") is not None:
            power = self.expect("num")
        self.expect("op", "(")
        args = [self.sum()]
        while self.take("op", ",") is not None:
            args.append(self.sum())
        self.expect("op", ")")
        if name not in ("min", "max") and len(args) != 1:
            raise _Fail()
        return ("call", name, args, power)


def _log_star(x):
    count = 0
    while x > 1:
        x = math.log2(x)
        count += 1
    return max(1, count)


def _evaluate(tree, env, cost):
    kind = tree[0]
    if kind == "num":
        return tree[1]
    if kind == "var":
        v = env[tree[1]]
        if cost:
            v = max(v, 2.0 if tree[1] == "n" else 1.0)
        return v
    if kind == "op":
        return _BINARY[tree[1]](_evaluate(tree[2], env, cost), _evaluate(tree[3], env, cost))
    _, name, args, power = tree
    values = [_evaluate(a, env, cost) for a in args]
    if name == "log":
        return (max(1.0, math.log2(max(values[0], 2.0))) if cost else math.log2(values[0])) ** power
    return _FUNCTIONS[name](values)


_FUNCTIONS = {"log*": lambda v: _log_star(v[0]), "min": min, "max": max, "sqrt": lambda v: math.sqrt(v[0]),
              "ceil": lambda v: math.ceil(v[0]), "floor": lambda v: math.floor(v[0])}


def _mentions(tree, variable):
    if tree[0] == "var":
        return tree[1] == variable
    if tree[0] == "op":
        return _mentions(tree[2], variable) or _mentions(tree[3], variable)
    return tree[0] == "call" and any(_mentions(a, variable) for a in tree[2])


def _terms(tree):
    """The additive terms of a bound, through sums and the arguments of min and max."""
    if tree[0] == "op" and tree[1] == "+":
        return _terms(tree[2]) + _terms(tree[3])
    if tree[0] == "call" and tree[1] in ("min", "max"):
        return [term for argument in tree[2] for term in _terms(argument)]
    return [tree]


class TimeBound:
    """A claimed time bound f(n, r), evaluated in cost mode."""

    def __init__(self, text, tree):
        self.text = text
        self._tree = tree

    def __call__(self, n, r):
        return _evaluate(self._tree, {"n": float(n), "r": float(r)}, cost=True)

    def terms(self):
        """Its additive terms (through sums, min and max), each a TimeBound: "n*r+r^5" gives n*r and r^5."""
        return [TimeBound(self.text, term) for term in _terms(self._tree)]


def parse_time_bound(text):
    """The TimeBound for text, or None when text is not in the grammar."""
    text = text.strip()
    if text.startswith("O(") and text.endswith(")"):
        text = text[2:-1]
    try:
        return TimeBound(text, _Parser(_tokens(text), ("n", "r")).whole())
    except (_Fail, IndexError):
        return None


class PieceBound:
    """A claimed piece count: relation and expression over n, r, h (the holes) and OPT."""

    def __init__(self, text, relation, tree):
        self.text = text
        self.relation = relation
        self._tree = tree
        self.uses_opt = _mentions(tree, "OPT")

    def value(self, n, r, opt=None, h=0):
        return _evaluate(self._tree, {"n": n, "r": r, "h": h, "OPT": opt}, cost=False)

    def holds(self, pieces, n, r, opt=None, h=0):
        """Whether pieces satisfies the bound (exactly, with a 1e-9 relative slack for decimals)."""
        v = self.value(n, r, opt, h)
        slack = 1e-9 * max(1.0, abs(v))
        return {"==": abs(pieces - v) <= slack, "<=": pieces <= v + slack, ">=": pieces >= v - slack,
                "<": pieces < v + slack, ">": pieces > v - slack}[self.relation]


def parse_piece_bound(text):
    """The PieceBound for text such as "<= 4*OPT", or None when it is not in the grammar."""
    text = text.strip()
    for relation in _RELATIONS:
        if text.startswith(relation):
            try:
                tree = _Parser(_tokens(text[len(relation):]), ("n", "r", "h", "OPT")).whole()
            except (_Fail, IndexError):
                return None
            return PieceBound(text, relation, tree)
    return None
