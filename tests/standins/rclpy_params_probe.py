"""A node's parameters as rclpy handles them: run with robotmodel's rclpy, and (imports swapped) with the real one.

``python rclpy_params_probe.py --ros-args -p rate:=5 -p gains:=[1.0,2.5] -p names:=[a,b] -p wrong:=abc
--params-file FILE`` (FILE giving ``label``) prints one line per observation; the test runs
it twice and compares the lines.
"""

import sys

from robotmodel import rclpy
from robotmodel.msgs.rcl_interfaces.msg import IntegerRange, ParameterDescriptor, SetParametersResult
from robotmodel.rclpy.node import Node
from robotmodel.rclpy.parameter import Parameter


def show(param):
    value = param.value
    print(param.name, param.type_.name, list(value) if isinstance(value, (list, tuple)) or hasattr(value, "typecode")
          else value)


def attempt(what, call):
    try:
        out = call()
    except Exception as exc:
        print(what, "raised", type(exc).__name__, exc)
    else:
        if isinstance(out, list):
            for result in out:
                print(what, result.successful, result.reason)
        else:
            print(what, "ok")


def main():
    rclpy.init(args=sys.argv)
    node = Node("probe")
    show(node.declare_parameter("rate", 1))
    show(node.declare_parameter("gains", [0.0]))
    show(node.declare_parameter("names", ["x"]))
    show(node.declare_parameter("label", "none"))
    show(node.declare_parameter("flag", True))
    show(node.get_parameter("use_sim_time"))
    attempt("wrong override", lambda: node.declare_parameter("wrong", 1))
    attempt("redeclare", lambda: node.declare_parameter("rate", 2))
    attempt("undeclared get", lambda: node.get_parameter("missing"))
    attempt("undeclared set", lambda: node.set_parameters([Parameter("missing", value=1)]))
    attempt("wrong type", lambda: node.set_parameters([Parameter("rate", value="fast")]))
    node.declare_parameter("count", Parameter.Type.INTEGER)
    attempt("uninitialized", lambda: node.get_parameter("count"))
    node.declare_parameter("fixed", 3, ParameterDescriptor(read_only=True))
    attempt("read only", lambda: node.set_parameters([Parameter("fixed", value=4)]))
    node.declare_parameter("level", 5, ParameterDescriptor(integer_range=[IntegerRange(from_value=0, to_value=10,
                                                                                        step=1)]))
    attempt("out of range", lambda: node.set_parameters([Parameter("level", value=11)]))

    def no_negative_rate(params):
        for param in params:
            if param.name == "rate" and param.value < 0:
                return SetParametersResult(successful=False, reason="rate must not be negative")
        return SetParametersResult(successful=True)

    node.add_on_set_parameters_callback(no_negative_rate)
    attempt("negative", lambda: node.set_parameters([Parameter("rate", value=-1)]))
    attempt("typed array", lambda: node.set_parameters([Parameter("gains", Parameter.Type.DOUBLE_ARRAY, [3.0])]))
    show(node.get_parameter("rate"))
    show(node.get_parameter("gains"))
    print([p.name for p in node.get_parameters(["rate", "flag"])])
    # ros2 param delete: a set to NOT_SET, refused for a statically typed parameter, undeclaring a dynamic one.
    attempt("delete static", lambda: node.set_parameters([Parameter("flag")]))
    node.declare_parameter("loose", 1, ParameterDescriptor(dynamic_typing=True))
    attempt("delete dynamic", lambda: node.set_parameters([Parameter("loose")]))
    print("loose", node.has_parameter("loose"), "flag", node.has_parameter("flag"))
    node.get_logger().info("parameters done")
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
