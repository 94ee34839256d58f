#!/usr/bin/env python3
"""Scores `spinhash scene` output against make_scene_tile.py's truth:
score_scene.py TRUTH.csv OUT.jsonl SLOPE TILE -> one CSV line:
tile,slope,vehicles,found,top1,confident_right,false_alarms,time_ms
A vehicle is found when a vehicle-kind object's centre lies within 2.5 m of (the truth is the
placed point mean, the object centre its footprint centre: up to 2 m apart on 10 m vehicles)
it; a false alarm is a confident answer on anything else or a wrong confident model."""
import csv
import json
import math
import sys

truth = list(csv.DictReader(open(sys.argv[1])))
objs = [json.loads(l) for l in open(sys.argv[2])]
vehicles = [t for t in truth if t["kind"] == "vehicle"]
found = top1 = right_conf = 0
used = set()
for v in vehicles:
    best, bd = None, 2.5
    for k, o in enumerate(objs):
        d = math.hypot(o["center"][0] - float(v["x"]), o["center"][1] - float(v["y"]))
        if d < bd and o["kind"] == "vehicle":
            best, bd = k, d
    if best is None:
        continue
    used.add(best)
    found += 1
    top1 += objs[best]["model"] == v["name"]
    right_conf += objs[best]["model"] == v["name"] and objs[best]["confident"]
false_alarms = sum(1 for k, o in enumerate(objs) if o["confident"] and (k not in used))
false_alarms += sum(1 for k in used if objs[k]["confident"] and not any(
    objs[k]["model"] == v["name"] and math.hypot(objs[k]["center"][0] - float(v["x"]), objs[k]["center"][1] - float(v["y"])) < 2.5
    for v in vehicles))
t_ms = objs[0]["time_ms"] if objs else 0
print("%s,%s,%d,%d,%d,%d,%d,%.0f" % (sys.argv[4], sys.argv[3], len(vehicles), found, top1, right_conf, false_alarms, t_ms))
