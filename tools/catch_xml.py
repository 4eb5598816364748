"""Reads Catch2's XML report (-r xml) into plain test-case records.

Shared by the test of the tests (tests/meta) and the grader, so both read a report the
same way. Step and points come from the tags [step:N:name] and [points:P]."""
from dataclasses import dataclass, field
import re
import xml.etree.ElementTree as ElementTree


UNKNOWN_EXPRESSION = "{Unknown expression after the reported line}"


@dataclass
class CaseResult:
    name: str
    tags: list
    passed: bool
    failures: list = field(default_factory=list)

    def tag_value(self, prefix):
        return next((t[len(prefix):] for t in self.tags if t.startswith(prefix)), None)

    @property
    def step(self):
        """(number, name) of the [step:N:name] tag, or None."""
        value = self.tag_value("step:")
        if value is None or ":" not in value:
            return None
        number, name = value.split(":", 1)
        return (int(number), name) if number.isdigit() else None

    @property
    def points(self):
        value = self.tag_value("points:")
        return float(value) if value is not None else 0.0


def parse_tags(text):
    return re.findall(r"\[([^\]]+)\]", text or "")


def parse(xml_text):
    """All test cases in a report; raises ValueError when the text is not a Catch2 XML report."""
    # Catch2 escapes the '>' of a ']]>' in a text only from the fourth character on, so a
    # message that starts with ']]>' (an exception's, say) is not well-formed XML. Catch2
    # writes no CDATA section, so every ']]>' in a report is text: escaped here.
    if isinstance(xml_text, bytes):
        xml_text = xml_text.replace(b"]]>", b"]]&gt;")
    else:
        xml_text = xml_text.replace("]]>", "]]&gt;")
    try:
        root = ElementTree.fromstring(xml_text)
    except ElementTree.ParseError as error:
        raise ValueError(f"not a Catch2 XML report: {error}") from None
    if root.tag != "Catch2TestRun":
        raise ValueError(f"not a Catch2 XML report: root element <{root.tag}>")
    cases = []
    for case in root.iter("TestCase"):
        failures = []
        for node in case.iter():
            if node.tag in ("Failure", "Exception", "FatalErrorCondition"):
                prefix = {"Exception": "your code threw an exception: ",
                          "FatalErrorCondition": "your code crashed: "}.get(node.tag, "")
                failures.append(prefix + (node.text or "").strip())
            elif node.tag == "Expression" and node.get("success") == "false":
                expanded = node.find("Expanded")
                text = expanded.text.strip() if expanded is not None and expanded.text else ""
                # Catch2's placeholder when an exception or a crash ended the case: the
                # Exception/FatalErrorCondition beside it says what happened.
                if text != UNKNOWN_EXPRESSION:
                    failures.append("check failed: " + text)
        result = case.find("OverallResult")
        passed = result is not None and result.get("success") == "true" and not failures
        cases.append(CaseResult(case.get("name", ""), parse_tags(case.get("tags")), passed, failures))
    return cases


# Characters Catch2's test-spec parser treats specially; a backslash makes them literal.
SPEC_SPECIAL = set('\\,[]"*~^&#')


def escape_test_name(name):
    """A test case name as a Catch2 test-spec text that matches that name and no other."""
    return "".join("\\" + c if c in SPEC_SPECIAL else c for c in name)


def case_spec(name, tags):
    """The Catch2 test spec of exactly one test case: its tags and its name, all required.

    A name alone is not enough: two chapters may hold a test of the same name (chapters 1
    and 2 both have "an immovable body on either side, and two immovable bodies"), and a
    spec by name would run both, judging one chapter by the other's code. Catch2 refuses
    two cases with the same name and the same tags, so name and tags pick one case."""
    return "".join(f"[{escape_test_name(tag)}]" for tag in tags) + escape_test_name(name)


def parse_listing(xml_text):
    """[(name, tags)] of `--list-tests --reporter xml`, in the order Catch2 lists them;
    raises ValueError when the text is not such a listing."""
    try:
        root = ElementTree.fromstring(xml_text)
    except ElementTree.ParseError as error:
        raise ValueError(f"not a Catch2 test listing: {error}") from None
    if root.tag != "MatchingTests":
        raise ValueError(f"not a Catch2 test listing: root element <{root.tag}>")
    return [((case.findtext("Name") or "").strip(), parse_tags(case.findtext("Tags")))
            for case in root.iter("TestCase")]
