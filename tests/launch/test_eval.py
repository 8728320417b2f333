"""$(eval): the interpreted Python subset computes like Python and refuses everything else."""

from __future__ import annotations

import math

import pytest

from robotmodel.launch._eval import EvalError, safe_eval


@pytest.mark.parametrize(("text", "expected"), [
    ("1 + 2 * 3", 7),
    ("x * 2 if flag else -1", 20),
    ("not flag or x > 3", True),
    ("1 < x <= 10", True),
    ("'a_' + name.upper()", "a_ROBOT"),
    ("name.endswith('bot') and len(name) == 5", True),
    ("[1, 2, 3][1:]", [2, 3]),
    ("int('4') + float('0.5')", 4.5),
    ("max(x, 3) % 7", 3),
    ("2 ** 10", 1024),
    ("sqrt(x * 10)", 10.0),
    ("math.pi / 2", math.pi / 2),
])
def test_computes_like_python(text, expected):
    names = {"x": 10, "flag": True, "name": "robot", "math": math}
    assert safe_eval(text, names, {"sqrt": math.sqrt}) == expected == eval(text, {"sqrt": math.sqrt}, names)


@pytest.mark.parametrize(("text", "reason"), [
    ("__import__('os')", "function '__import__' is not available"),
    ("open('/etc/passwd')", "function 'open' is not available"),
    ("().__class__", "attribute '().__class__' is not allowed"),
    ("'{0.__class__}'.format(1)", "call "),
    ("name.__len__()", "call "),
    ("[c for c in 'ab']", "is not allowed in $(eval)"),
    ("lambda: 1", "is not allowed in $(eval)"),
    ("'a' * 10 ** 9", "result too large"),
    ("2 ** 100000", "exponent 100000 too large"),
    ("'%999999999s' % 'a'", "string formatting"),
    ("('a' * 1000000).replace('a', 'a' * 1000000)", "result too large"),
    ("''.join(['a' * 1000000] * 1000000)", "result too large"),
    ("x = 1", "invalid expression"),
    ("undefined_name + 1", "name 'undefined_name' is not defined"),
    ("1 / 0", "ZeroDivisionError"),
])
def test_refuses(text, reason):
    with pytest.raises(EvalError) as info:
        safe_eval(text, {"name": "robot"}, {})
    assert reason in str(info.value)


@pytest.mark.parametrize("text", ["(" * 100000 + "1" + ")" * 100000, "-" * 100000 + "1", "not " * 100000 + "1",
                                  "-" * 150 + "1"], ids=["parentheses", "minus", "not", "minus150"])
def test_deep_nesting_is_an_error_not_a_crash(text):
    with pytest.raises(EvalError, match=r"invalid expression|too deep"):
        safe_eval(text, {}, {})


# -- ROS 1 $(eval): the args typed as roslaunch types them ---------------------------------------------
# roslaunch's _eval hands arg('x') and a bare x over as convert_value(value, 'auto'): a float
# when the text holds '.', else an int (none with '_'), else true/false in any case as a
# bool, else the text; a bare name is looked up among its functions, true/false and math's
# names before the args. It writes the result back with Python's str(). The expected texts
# are Python computing on the values so typed.
@pytest.mark.parametrize(("args", "expr", "expected"), [
    ({"radius": "0.5"}, "2 * 3.1415 * arg('radius')", str(2 * 3.1415 * 0.5)),
    ({"radius": "0.5"}, "2 * radius", str(2 * 0.5)),
    ({"n": "3"}, "arg('n') + 1", str(3 + 1)),
    ({"gui": "false"}, "not arg('gui')", str(not False)),
    ({"gui": "False"}, "arg('gui') == False", str(True)),
    ({"gui": "TRUE"}, "gui and 1", str(True and 1)),
    ({"e": "1e3"}, "arg('e') + 'x'", "1e3" + "x"),
    ({"u": "1_000"}, "arg('u') + '!'", "1_000" + "!"),
    ({"name": "robot"}, "arg('name') + '_1'", "robot" + "_1"),
    ({"pi": "3"}, "pi", str(math.pi)),
    ({}, "sin(pi / 2) + floor(2.5)", str(math.sin(math.pi / 2) + math.floor(2.5))),
])
def test_ros1_eval_types_args_as_roslaunch(pkg, args, expr, expected):
    from robotmodel.launch import load_launch_file

    declared = "".join(f'<arg name="{k}"/>' for k in args)
    path = pkg.launch("eval.launch", f'<launch>{declared}<param name="out" value="$(eval {expr})"/></launch>')
    assert load_launch_file(path, args, [pkg.root]).params["/out"].value == expected


@pytest.mark.parametrize(("gui", "started"), [("false", ["no_gui"]), ("true", ["gui"])])
def test_ros1_eval_not_arg_false_chooses_the_right_nodes(pkg, gui, started):
    from robotmodel.launch import load_launch_file

    path = pkg.launch("gui.launch", """
        <launch>
          <arg name="gui" default="true"/>
          <node pkg="tf" type="static_transform_publisher" name="gui" args="0 0 0 0 0 0 a b 100"
                if="$(eval arg('gui'))"/>
          <node pkg="tf" type="static_transform_publisher" name="no_gui" args="0 0 0 0 0 0 a c 100"
                if="$(eval not arg('gui'))"/>
        </launch>
    """)
    assert [n.name for n in load_launch_file(path, {"gui": gui}, [pkg.root]).nodes] == started
