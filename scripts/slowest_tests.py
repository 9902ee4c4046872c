"""Print the N slowest tests of a pytest JUnit XML report (setup, call and teardown
together), slowest first: .ci/run's list after its step table.

    usage: python scripts/slowest_tests.py REPORT.xml [N]
"""
import sys
import xml.etree.ElementTree as ET


def main(path: str, n: int) -> None:
    cases = [(float(c.get("time", 0)), f"{c.get('classname')}::{c.get('name')}")
             for c in ET.parse(path).iter("testcase")]
    cases.sort(reverse=True)
    print(f"The main suite's {min(n, len(cases))} slowest of {len(cases)} tests "
          f"(setup + call + teardown; all of them {sum(t for t, _ in cases):.0f} s):")
    for seconds, name in cases[:n]:
        print(f"{seconds:8.2f} s  {name}")


if __name__ == "__main__":
    if len(sys.argv) not in (2, 3):
        raise SystemExit(__doc__)
    main(sys.argv[1], int(sys.argv[2]) if len(sys.argv) == 3 else 20)
