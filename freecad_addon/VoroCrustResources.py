"""Where the VoroCrust add-on's files are (InitGui.py runs without a __file__ of its own)."""

import os

ADDON_DIR = os.path.dirname(os.path.abspath(__file__))


def icon(name):
    """The path of an icon in Resources/icons."""
    return os.path.join(ADDON_DIR, "Resources", "icons", name)
