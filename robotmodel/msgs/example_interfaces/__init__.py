"""example_interfaces: ``from robotmodel.msgs.example_interfaces.srv import AddTwoInts``."""
