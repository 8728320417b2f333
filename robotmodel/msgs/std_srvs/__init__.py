"""std_srvs: ``from robotmodel.msgs.std_srvs.srv import Trigger``."""
