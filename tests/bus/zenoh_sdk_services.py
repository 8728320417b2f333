"""ROS 2 services through an rmw_zenoh implementation that is not ours: zenoh-ros2-sdk (PyPI), in its own process.

``python zenoh_sdk_services.py ROLE PORT ...`` joins ROS_DOMAIN_ID's domain through the router at
tcp/127.0.0.1:PORT. The SDK builds its own key expressions, liveliness tokens, attachments and
RIHS01 type hashes (computed from the .srv/.msg texts below, ROS 2 Jazzy's rcl_interfaces
without comments): none of robotmodel's code is imported here. Roles:

- ``param_client PORT NODE URDF``: the parameter client of node NODE. Calls ``NODE/list_parameters``,
  ``NODE/get_parameters`` [robot_description, publish_frequency], ``NODE/set_parameters``
  (robot_description := the text of file URDF; publish_frequency := "fast", a wrong type), then
  get_parameters again; prints one JSON line per answer (``list``, ``reply_attachment``: what the
  attachment of one more list reply holds, ``get``, ``set``, ``get``),
  ``timeout NAME`` for a call not answered.
- ``add_server PORT``: serves ``/add_two_ints`` (example_interfaces/srv/AddTwoInts, sum = a + b) as
  node ``sdk_adder``, prints ``ready``, then ``served A B`` per request, until stdin closes.
"""

from __future__ import annotations

import json
import sys
import tempfile
import threading
import time
from pathlib import Path
from typing import Any

import numpy as np
import zenoh
from zenoh_ros2_sdk import ROS2ServiceClient, ROS2ServiceServer, get_registry
from zenoh_ros2_sdk.attachment import Attachment

# Jazzy's texts (rcl_interfaces, example_interfaces), comments left out and the package named in each
# field type (ROS allows both; the SDK's parser looks for a bare name under pkg/srv/msg/).
TEXTS = {
    "rcl_interfaces/srv/GetParameters.srv": "string[] names\n---\nrcl_interfaces/ParameterValue[] values\n",
    "rcl_interfaces/srv/ListParameters.srv": "uint64 DEPTH_RECURSIVE=0\nstring[] prefixes\nuint64 depth\n---\n"
                                             "rcl_interfaces/ListParametersResult result\n",
    "rcl_interfaces/srv/SetParameters.srv": "rcl_interfaces/Parameter[] parameters\n---\n"
                                            "rcl_interfaces/SetParametersResult[] results\n",
    "rcl_interfaces/msg/Parameter.msg": "string name\nrcl_interfaces/ParameterValue value\n",
    "rcl_interfaces/msg/ParameterValue.msg": "uint8 type\nbool bool_value\nint64 integer_value\n"
                                             "float64 double_value\nstring string_value\nbyte[] byte_array_value\n"
                                             "bool[] bool_array_value\nint64[] integer_array_value\n"
                                             "float64[] double_array_value\nstring[] string_array_value\n",
    "rcl_interfaces/msg/SetParametersResult.msg": "bool successful\nstring reason\n",
    "rcl_interfaces/msg/ListParametersResult.msg": "string[] names\nstring[] prefixes\n",
    "example_interfaces/srv/AddTwoInts.srv": "int64 a\nint64 b\n---\nint64 sum\n",
}
# rcl_interfaces/msg/ParameterType's constants.
STRING, DOUBLE = 4, 3
TIMEOUT_S = 20.0


def say(*parts: str) -> None:
    sys.stdout.write(" ".join(parts) + "\n")
    sys.stdout.flush()


def value_json(v: Any) -> dict[str, Any]:
    return {"type": int(v.type), "string": str(v.string_value), "double": float(v.double_value)}


def param_client(port: int, node: str, urdf: str) -> None:
    def client(name: str, srv: str) -> ROS2ServiceClient:
        return ROS2ServiceClient(f"{node}/{name}", f"rcl_interfaces/srv/{srv}", node_name="sdk_param_client",
                                 router_port=port, timeout=TIMEOUT_S)

    lister, getter, setter = (client("list_parameters", "ListParameters"), client("get_parameters", "GetParameters"),
                              client("set_parameters", "SetParameters"))
    store = setter.session_mgr.store
    value_cls = store.types["rcl_interfaces/msg/ParameterValue"]
    param_cls = store.types["rcl_interfaces/msg/Parameter"]

    def call(c: ROS2ServiceClient, what: str, **fields: Any) -> Any:
        response = c.call(**fields)
        if response is None:
            say("timeout", what)
            raise SystemExit(1)
        return response

    def blank(**over: Any) -> Any:
        fields: dict[str, Any] = {"type": 0, "bool_value": False, "integer_value": 0, "double_value": 0.0,
                                  "string_value": "", "byte_array_value": [], "bool_array_value": [],
                                  "integer_array_value": [], "double_array_value": [], "string_array_value": []}
        fields.update(over)
        for key in ("byte_array_value", "integer_array_value", "double_array_value"):
            fields[key] = np.array(fields[key], dtype={"byte_array_value": np.uint8, "integer_array_value": np.int64,
                                                       "double_array_value": np.float64}[key])
        fields["bool_array_value"] = np.array(fields["bool_array_value"], dtype=np.bool_)
        return value_cls(**fields)

    listing = call(lister, "list", prefixes=[], depth=0)
    say("list", json.dumps(sorted(listing.result.names)))
    say("reply_attachment", json.dumps(reply_attachment(lister)))
    names = ["robot_description", "publish_frequency"]
    say("get", json.dumps([value_json(v) for v in call(getter, "get", names=names).values]))
    sets = [param_cls(name="robot_description", value=blank(type=STRING, string_value=urdf)),
            param_cls(name="publish_frequency", value=blank(type=STRING, string_value="fast"))]
    results = call(setter, "set", parameters=sets).results
    say("set", json.dumps([[bool(r.successful), str(r.reason)] for r in results]))
    say("get", json.dumps([value_json(v) for v in call(getter, "get", names=names).values]))


def reply_attachment(client: ROS2ServiceClient) -> dict[str, Any]:
    """One more list request through the SDK's own querier, to read the reply's attachment.

    rmw_zenoh's client takes a reply only with an attachment and pairs it with its request by
    the sequence number read there (rmw_client_data.cpp, take_response); the SDK's ``call``
    does not look at it, so it is read here with the SDK's own attachment code.
    """
    seq, sent = 41, time.time_ns()
    request = client.request_msg_class(prefixes=[], depth=0)
    payload = bytes(client.session_mgr.store.serialize_cdr(request, client.request_store_type))
    replies: list[Any] = []
    done = threading.Event()

    def on_reply(reply: Any) -> None:
        if reply.ok is not None:
            att = reply.ok.attachment
            replies.append(None if att is None else Attachment.from_bytes(att.to_bytes()))
            done.set()

    client.querier.get(on_reply, payload=zenoh.ZBytes(payload),
                       attachment=zenoh.ZBytes(Attachment(sequence_id=seq, timestamp_ns=sent,
                                                          gid=client.client_gid).to_bytes()))
    if not done.wait(TIMEOUT_S) or replies[0] is None:
        return {"attachment": None}
    att = replies[0]
    return {"sequence_number": att.sequence_id, "sent": seq, "gid_is_the_client's": att.gid == client.client_gid,
            "stamped_after_the_request": att.timestamp_ns >= sent}


def add_server(port: int) -> None:
    def add(request: Any) -> Any:
        say("served", str(request.a), str(request.b))
        return server.response_msg_class(sum=request.a + request.b)

    server = ROS2ServiceServer("/add_two_ints", "example_interfaces/srv/AddTwoInts", callback=add,
                               node_name="sdk_adder", router_port=port)
    say("ready")
    sys.stdin.read()
    server.close()


def main(role: str, port: int, *args: str) -> int:
    with tempfile.TemporaryDirectory() as texts:
        for name, text in TEXTS.items():
            path = Path(texts, name)
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text)
            if name.endswith(".srv"):
                # The halves as .msg files too, else the SDK tries to git-clone them before reading the .srv;
                for half, part in zip(("_Request", "_Response"), text.split("---\n"), strict=True):
                    path.with_name(path.stem + half + ".msg").write_text(part)
        get_registry(texts)
        if role == "param_client":
            param_client(port, args[0], Path(args[1]).read_text())
        elif role == "add_server":
            add_server(port)
        else:
            raise SystemExit(f"unknown role {role}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], int(sys.argv[2]), *sys.argv[3:]))
