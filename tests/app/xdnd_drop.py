#!/usr/bin/python3
# Drops a file onto the first X window that accepts drops (XDND protocol, as a file manager does).
# usage: xdnd_drop.py FILE [timeout seconds]
import os
import sys
import time
import urllib.parse

from Xlib import X, Xatom, display, protocol

path = os.path.abspath(sys.argv[1])
deadline = time.time() + (float(sys.argv[2]) if len(sys.argv) > 2 else 30)
d = display.Display()
root = d.screen().root
atom = lambda name: d.intern_atom(name)
XdndAware, XdndSelection = atom("XdndAware"), atom("XdndSelection")
XdndEnter, XdndPosition, XdndStatus = atom("XdndEnter"), atom("XdndPosition"), atom("XdndStatus")
XdndDrop, XdndFinished, XdndActionCopy = atom("XdndDrop"), atom("XdndFinished"), atom("XdndActionCopy")
uri_list = atom("text/uri-list")


def find_aware(window):
    try:
        if window.get_full_property(XdndAware, X.AnyPropertyType):
            return window
        for child in window.query_tree().children:
            found = find_aware(child)
            if found:
                return found
    except Exception:
        pass
    return None


target = None
while target is None and time.time() < deadline:
    target = find_aware(root)
    if target is None:
        time.sleep(0.2)
if target is None:
    sys.exit("no window accepts drops")
time.sleep(1.0)  # let the program finish its first frames

source = root.create_window(0, 0, 1, 1, 0, X.CopyFromParent)
source.set_selection_owner(XdndSelection, X.CurrentTime)
d.flush()


def send(kind, data):
    event = protocol.event.ClientMessage(window=target, client_type=kind, data=(32, data))
    target.send_event(event, event_mask=0)
    d.flush()


geometry = target.get_geometry()
origin = target.translate_coords(root, 0, 0)
x, y = -origin.x + geometry.width // 2, -origin.y + geometry.height // 2
send(XdndEnter, [source.id, 5 << 24, uri_list, 0, 0])
send(XdndPosition, [source.id, 0, (x << 16) | y, X.CurrentTime, XdndActionCopy])

dropped = finished = False
payload = ("file://" + urllib.parse.quote(path) + "\r\n").encode()
while not finished and time.time() < deadline:
    while d.pending_events():
        e = d.next_event()
        if e.type == X.ClientMessage and e.client_type == XdndStatus and not dropped:
            if not e.data[1][1] & 1:
                sys.exit("the window refused the drop")
            send(XdndDrop, [source.id, 0, X.CurrentTime, 0, 0])
            dropped = True
        elif e.type == X.SelectionRequest:
            e.requestor.change_property(e.property, e.target, 8, payload)
            notify = protocol.event.SelectionNotify(time=e.time, requestor=e.requestor, selection=e.selection,
                                                    target=e.target, property=e.property)
            e.requestor.send_event(notify)
            d.flush()
        elif e.type == X.ClientMessage and e.client_type == XdndFinished:
            finished = True
    time.sleep(0.01)
if not finished:
    sys.exit("the drop did not finish")
print("dropped", path)
