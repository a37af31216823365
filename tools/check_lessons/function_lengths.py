#!/usr/bin/env python3
"""The lengths of the functions in C++ source files, counted as clang-tidy's readability-function-size counts them
(the line of a body's closing brace minus the line of its opening one), without parsing C++: a scanner that knows
comments, string and character literals (raw strings too), preprocessor lines and which braces open a namespace, a
class, a function body or an initialiser.

What counts as a function is what clang-tidy counts: free functions, member functions and constructors, with the
lambdas and local classes written inside a function counted as part of it. A lambda at namespace scope (an
initialiser, like a data table) is not counted, as clang-tidy does not count it. Preprocessor conditionals are not
evaluated: every branch is read. Over the chapters it finds what clang-tidy 14 finds, file, line, name and length:
89 functions over 30 lines, 23 over 50, and the same 447 of one line or more.

    tools/function_lengths.py [--max N | --all] FILE...

--max N (default 80) prints each function longer than N lines as `FILE:LINE: function 'NAME' has L lines (at most
N)`, LINE being the line of its name, and exits with status 1 when there is one; --all prints every function with its
length (`FILE:LINE: NAME L`) and exits with 0. Status 2: a file could not be read or its braces do not balance.
"""
import re
import sys

IDENTIFIER = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
NUMBER = re.compile(r"\.?[0-9](?:[eEpP][+-]|'(?=[0-9A-Za-z])|[0-9A-Za-z_.])*")
STRING_PREFIX = re.compile(r"(?:u8|u|U|L)?R?\"")
# Multi-character punctuators that must not be read as a lone '=' or ':'; everything else is one character.
PUNCTUATORS = ("::", "->", "<<=", ">>=", "==", "!=", "<=", ">=", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=")


class Token:
    __slots__ = ("text", "line")

    def __init__(self, text, line):
        self.text = text
        self.line = line


def block_comment_end(source, i):
    """The index just past the /* ... */ comment that starts at i (the end of the text if it never closes)."""
    end = source.find("*/", i + 2)
    return len(source) if end < 0 else end + 2


def tokens(source):
    """The tokens of `source` that matter for finding bodies: identifiers, numbers, punctuators; each string or
    character literal is one token "S"; comments and preprocessor lines are dropped."""
    out = []
    i, line, n = 0, 1, len(source)
    at_line_start = True
    while i < n:
        c = source[i]
        if c == "\n":
            line += 1
            i += 1
            at_line_start = True
            continue
        if c in " \t\r\f\v":
            i += 1
            continue
        if c == "\\" and source.startswith("\n", i + 1):  # a line continuation outside a directive
            i += 2
            line += 1
            continue
        if c == "#" and at_line_start:  # a preprocessor line, with its continuations and comments
            while i < n and source[i] != "\n":
                if source.startswith("/*", i):
                    end = block_comment_end(source, i)
                    line += source.count("\n", i, end)
                    i = end
                    continue
                if source.startswith("//", i):
                    while i < n and source[i] != "\n":
                        i += 1
                    break
                if source[i] == "\\" and source.startswith("\n", i + 1):
                    line += 1
                    i += 2
                    continue
                i += 1
            continue
        at_line_start = False
        if source.startswith("//", i):
            while i < n and source[i] != "\n":
                if source[i] == "\\" and source.startswith("\n", i + 1):
                    line += 1
                    i += 1
                i += 1
            continue
        if source.startswith("/*", i):
            end = block_comment_end(source, i)
            line += source.count("\n", i, end)
            i = end
            continue
        prefix = STRING_PREFIX.match(source, i)
        if prefix:
            start_line = line
            j = prefix.end()
            if prefix.group().endswith('R"'):  # R"delimiter( ... )delimiter"
                open_paren = source.find("(", j)
                closing = ")" + source[j:open_paren] + '"'
                end = source.find(closing, open_paren + 1)
                end = n if end < 0 else end + len(closing)
            else:
                end = j
                while end < n and source[end] != '"':
                    if source[end] == "\\":
                        end += 1
                    end += 1
                end += 1
            line += source.count("\n", i, end)
            out.append(Token("S", start_line))
            i = end
            continue
        if c == "'" or (c in "uUL" and source.startswith("'", i + 1)) or source.startswith("u8'", i):
            j = source.index("'", i) + 1
            while j < n and source[j] != "'":
                if source[j] == "\\":
                    j += 1
                j += 1
            out.append(Token("S", line))
            i = j + 1
            continue
        match = NUMBER.match(source, i) or IDENTIFIER.match(source, i)
        if match:
            out.append(Token(match.group(), line))
            i = match.end()
            continue
        for p in PUNCTUATORS:
            if source.startswith(p, i):
                out.append(Token(p, line))
                i += len(p)
                break
        else:
            out.append(Token(c, line))
            i += 1
    return out


def matching(toks, k):
    """The index of the token closing the bracket opened at toks[k] ('(', '[' or '{')."""
    close = {"(": ")", "[": "]", "{": "}"}[toks[k].text]
    opener, depth = toks[k].text, 0
    for j in range(k, len(toks)):
        if toks[j].text == opener:
            depth += 1
        elif toks[j].text == close:
            depth -= 1
            if depth == 0:
                return j
    raise ValueError(f"line {toks[k].line}: '{opener}' is never closed")


def without_template_heads(decl):
    """The declaration's tokens with each `template <...>` head left out (its angles may hold '=' and 'class')."""
    out, k = [], 0
    while k < len(decl):
        if decl[k].text == "template" and k + 1 < len(decl) and decl[k + 1].text == "<":
            depth, k = 0, k + 1
            while k < len(decl):
                depth += {"<": 1, ">": -1}.get(decl[k].text, 0)
                k += 1
                if depth == 0:
                    break
            continue
        out.append(decl[k])
        k += 1
    return out


def top_level(decl):
    """The declaration's tokens outside parentheses, brackets and braces, each with its index in decl."""
    out, depth = [], 0
    for k, t in enumerate(decl):
        if t.text in "([{":
            depth += 1
        elif t.text in ")]}":
            depth -= 1
        elif depth == 0:
            out.append((k, t))
    return out


NOT_A_NAME = {"decltype", "alignas", "noexcept", "sizeof", "alignof", "__attribute__", "__declspec"}


def parameter_list(decl):
    """The index of the '(' opening the function's parameters: the first one outside template angles that follows
    a name (not `decltype(...)` or `alignas(...)`) or an operator's symbol, or None."""
    angles = 0
    for k, t in enumerate(decl):
        if t.text == "<" and k > 0 and (IDENTIFIER.fullmatch(decl[k - 1].text) or decl[k - 1].text == "::"):
            if decl[k - 1].text != "operator":
                angles += 1
        elif t.text == ">" and angles > 0 and decl[k - 1].text != "operator":
            angles -= 1
        elif t.text == "(" and angles == 0 and k > 0:
            before = decl[k - 1].text
            if (IDENTIFIER.fullmatch(before) and before not in NOT_A_NAME) or not IDENTIFIER.fullmatch(before) and \
                    any(decl[j].text == "operator" for j in range(max(k - 3, 0), k)):
                return k
    return None


def kind_of_brace(decl):
    """What a '{' opens at namespace or class scope, from the tokens of the declaration before it: 'namespace',
    'class', 'function' (with the function's name and the line it stands on), 'member-init' (a brace initialiser in a
    constructor's initialiser list) or 'data' (an initialiser, an enumeration)."""
    decl = without_template_heads(decl)
    words = [t.text for t in decl]
    if not words or words[0] == "namespace" or words[:2] == ["extern", "S"]:
        return "namespace", None
    if words[0] == "enum":
        return "data", None
    outside = top_level(decl)
    texts = [t.text for _, t in outside]
    # A class head: class/struct/union before any parenthesis (`struct Fabric : Base {`, `class alignas(16) X {`).
    for k, t in outside:
        if t.text in ("class", "struct", "union"):
            return "class", None
        if t.text == "(" or t.text == "=":
            break
    # '=' outside parentheses (not in `operator=`) makes it an initialiser, a lambda at namespace scope among them.
    for idx, (k, t) in enumerate(outside):
        if t.text == "=" and not (idx > 0 and texts[idx - 1] == "operator"):
            return "data", None
    paren = parameter_list(decl)
    if paren is None:
        return "data", None  # `Table t{...}`, `double g{9.81}`
    name = paren - 1
    if decl[name].text == "operator" and decl[paren + 1].text == ")":
        paren += 2  # operator()(...)
    for back in range(paren - 1, max(paren - 4, 0) - 1, -1):  # operator==, operator<<, operator double
        if decl[back].text == "operator":
            name = back
    close = matching(decl, paren)
    # After the parameters: a constructor's initialiser list `: a(x), b{y}` ends where a brace follows ')' or '}'.
    rest = [t.text for t in decl[close + 1:]]
    in_init_list = False
    depth = 0
    for t in rest:
        if t in "([{":
            depth += 1
        elif t in ")]}":
            depth -= 1
        elif t == ":" and depth == 0:
            in_init_list = True
    if in_init_list and decl[-1].text not in (")", "}"):
        return "member-init", None
    return "function", (name_of(decl, name, paren), decl[name].line)


def functions(toks):
    """(name, name's line, opening brace's line, closing brace's line) of each function body in the token list."""
    found = []
    scopes = ["namespace"]  # the kind of each open brace at namespace or class scope
    decl = []  # the tokens of the declaration being read at the current scope
    k = 0
    while k < len(toks):
        t = toks[k]
        if t.text == "{":
            kind, name = kind_of_brace(decl)
            if kind == "function":
                end = matching(toks, k)
                found.append((name[0], name[1], t.line, toks[end].line))
                decl, k = [], end + 1
                continue
            if kind in ("data", "member-init"):
                end = matching(toks, k)
                decl += toks[k:end + 1]
                k = end + 1
                continue
            scopes.append(kind)
            decl, k = [], k + 1
            continue
        if t.text == "}":
            if len(scopes) == 1:
                raise ValueError(f"line {t.line}: '}}' closes nothing")
            scopes.pop()
            decl, k = [], k + 1
            continue
        if t.text == ";" or (t.text == ":" and len(decl) == 1 and decl[0].text in ("public", "private", "protected")):
            decl, k = [], k + 1
            continue
        if t.text in ("(", "["):  # parameter lists and attributes may hold braces (default arguments)
            end = matching(toks, k)
            decl += toks[k:end + 1]
            k = end + 1
            continue
        decl.append(t)
        k += 1
    if len(scopes) != 1:
        raise ValueError("a '{' is never closed")
    return found


def name_of(decl, k, paren):
    """The function's name as written at its definition, qualified (`Fabric::forces`, `operator()`): the tokens from
    decl[k] up to its parameter list, which opens at decl[paren]."""
    start = k
    if start > 0 and decl[start - 1].text == "~":
        start -= 1
    while start >= 2 and decl[start - 1].text == "::" and IDENTIFIER.fullmatch(decl[start - 2].text):
        start -= 2
    name = "".join(t.text for t in decl[start:k + 1])
    for t in decl[k + 1:paren]:  # operator==, operator(), operator double
        name += " " + t.text if IDENTIFIER.fullmatch(t.text) else t.text
    return name


def main(argv):
    limit, list_all, files = 80, False, []
    args = iter(argv)
    for a in args:
        if a == "--max":
            limit = int(next(args))
        elif a == "--all":
            list_all = True
        else:
            files.append(a)
    long_ones = 0
    for path in files:
        try:
            with open(path, encoding="utf-8") as f:
                found = functions(tokens(f.read()))
        except (OSError, ValueError, StopIteration) as e:
            print(f"function_lengths: {path}: {e}", file=sys.stderr)
            return 2
        for name, line, first, last in found:
            lines = last - first
            if list_all:
                print(f"{path}:{line}: {name} {lines}")
            elif lines > limit:
                print(f"{path}:{line}: function '{name}' has {lines} lines (at most {limit})")
                long_ones += 1
    return 1 if long_ones else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
