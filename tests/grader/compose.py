"""Builds a whole submission from a fragment and the reference solution.

A mutant or hostile case (tests/mutants/<chapter>/<name>/<source>.cpp,
tests/hostile/<name>/<source>.cpp) holds only what differs from solutions/<source>.cpp:

    // what the case does (its leading comment)
    #include <cstdlib>                     // extra includes and macros, before the namespace
    namespace workbook::inelastic {
    namespace { ... }                      // new helpers: put before the reference's functions
    Vector3 common_velocity(...) { ... }   // a function of the reference: replaces it
    }  // namespace workbook::inelastic

so each case shows its mistake and nothing else, and follows the reference when it changes.
The layout it relies on is the workbook's own: top-level blocks inside one namespace, each
ending with a '}' in the first column."""
import re

NAMESPACE_OPEN = re.compile(r"^namespace workbook(::[\w:]+)? \{")
FUNCTION_NAME = re.compile(r"^(?!namespace\b)[^(=]*?\b(\w+)\s*\(")


def _split(text):
    """(preamble lines, namespace line, blocks, trailer lines); each block is a list of lines
    with the comments just above it attached."""
    lines = text.splitlines()
    opening = next((i for i, line in enumerate(lines) if NAMESPACE_OPEN.match(line)), None)
    if opening is None:
        raise ValueError("no 'namespace workbook::... {' line")
    closing = max(i for i, line in enumerate(lines) if line.startswith("}  // namespace workbook"))
    blocks, current = [], []
    for line in lines[opening + 1:closing]:
        if not current and not line.strip():
            continue
        current.append(line)
        if line.startswith("}") or (line and not line[0].isspace() and line.rstrip().endswith(";")
                                    and not line.startswith("//") and len(current) == 1):
            blocks.append(current)
            current = []
    if any(line.strip() and not line.strip().startswith("//") for line in current):
        raise ValueError("a block inside the namespace does not end with '}' in the first column")
    return lines[:opening], lines[opening], blocks, lines[closing:]


def _name(block):
    for line in block:
        if line.strip() and not line.lstrip().startswith("//"):
            match = FUNCTION_NAME.match(line)
            return match.group(1) if match else None
    return None


def compose(reference_text, fragment_text, reference_label="the reference"):
    """The reference with the fragment's functions swapped in and its helpers and includes added.
    A fragment function the reference does not have is added as a helper."""
    ref_pre, ref_ns, ref_blocks, ref_trailer = _split(reference_text)
    frag_pre, _, frag_blocks, _ = _split(fragment_text)
    replacements = {}
    helpers = []
    reference_names = {_name(b) for b in ref_blocks}
    for block in frag_blocks:
        name = _name(block)
        if name is not None and name in reference_names:
            replacements[name] = block
        else:
            helpers.append(block)
    if not replacements and not helpers and not any(line.strip() and not line.startswith("//") for line in frag_pre):
        raise ValueError("the fragment changes nothing: it would grade as the reference")
    description = [line for line in frag_pre if line.startswith("//") and "compose.py" not in line]
    additions = [line for line in frag_pre if not line.startswith("//")]
    out = description + [f"// Composed by tests/grader/compose.py onto {reference_label}."]
    out += [line for line in ref_pre if not line.startswith("//")] + additions + [ref_ns, ""]
    for block in helpers + [replacements.get(_name(b), b) for b in ref_blocks]:
        out += block + [""]
    out += ref_trailer
    return "\n".join(out) + "\n"
