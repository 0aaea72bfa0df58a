"""`reportgen gear`."""
import json

from reportgen.cli import main

CONTRACT = ("alpha_w_deg", "aw", "y", "dy", "d1", "d2", "db1", "db2", "dw1", "dw2", "da1", "da2", "df1",
            "df2", "s1", "s2", "sa1", "sa2", "pb", "eps_alpha", "ab", "x1", "x2")


def test_table_prints_seed_numbers(capsys):
    assert main(["gear", "--z1", "13", "--z2", "26", "--module", "9", "--x1", "0.63", "--x2", "0.67"]) == 0
    out = capsys.readouterr().out
    for text in ("aw = 185.409", "142.758", "260.478", "εα = ab/pb = 1.1524", "[FAIL] transverse contact"):
        assert text in out


def test_json_has_the_contract_keys(capsys):
    assert main(["gear", "--z1", "13", "--z2", "26", "--module", "9", "--x1", "auto", "--x2", "auto",
                 "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert set(CONTRACT) <= set(data)
    assert data["all_checks_passed"] is True and "rule" in data["auto"]
    assert abs(data["aw"] - 184.0426) < 1e-3


def test_bad_option_exit_2(capsys):
    assert main(["gear", "--z1", "3", "--z2", "26", "--module", "9"]) == 2
    assert "--z1" in capsys.readouterr().err
    assert main(["gear", "--z1", "13", "--z2", "26", "--module", "9", "--x1", "auto"]) == 2
    assert "--x2" in capsys.readouterr().err
