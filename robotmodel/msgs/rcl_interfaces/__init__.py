"""rcl_interfaces: ``from robotmodel.msgs.rcl_interfaces.msg import ParameterDescriptor`` (and ``.srv``)."""
