#!/usr/bin/env python3
"""The example rasterizer (examples/python_rasterizer.py) behind a hello
and ids with the mistakes of issue 40, for tests/external_hello.rs. It
appends "case NAME" to LOG for every request it receives, so that a test
counts what was sent.

  hello_faults.py LOG [FLAGS]

  --no-id           answers carry no id
  --wrong-id        answers carry the program's own counter as id ("1", "2", ...)
  --all-edges       declares conventions.fill_rule all-edges
  --no-antialias    declares antialias: false
  --name-bytes N    a name of N bytes in its hello
  --set PATH=JSON   sets a key of its hello (PATH dotted under "hello"),
                    for hellos with mistakes: --set conventions.fillrule='"top-left"'
"""

import importlib.util
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLE = os.path.join(HERE, "..", "..", "examples", "python_rasterizer.py")
spec = importlib.util.spec_from_file_location("example", EXAMPLE)
example = importlib.util.module_from_spec(spec)
spec.loader.exec_module(example)


def value_of(args, flag):
    return args[args.index(flag) + 1] if flag in args else None


def main():
    log_path, args = sys.argv[1], sys.argv[2:]
    hello = json.loads(json.dumps(example.HELLO))
    inner = hello["hello"]
    inner["name"] = "hello-faults"
    if "--all-edges" in args:
        inner["conventions"]["fill_rule"] = "all-edges"
    if "--no-antialias" in args:
        inner["capabilities"]["antialias"] = False
    if value_of(args, "--name-bytes"):
        inner["name"] = "n" * int(value_of(args, "--name-bytes"))
    for i, a in enumerate(args):
        if a == "--set":
            path, text = args[i + 1].split("=", 1)
            keys = path.split(".")
            target = inner
            for key in keys[:-1]:
                target = target.setdefault(key, {})
            target[keys[-1]] = json.loads(text)
    print(json.dumps(hello), flush=True)
    counter = 0
    for text in sys.stdin:
        if not text.strip():
            continue
        request = json.loads(text)
        if request.get("bye"):
            break
        counter += 1
        with open(log_path, "a") as f:
            f.write("case %s\n" % request["case"])
        response = example.rasterize(request)
        if "--wrong-id" in args:
            response["id"] = str(counter)
        elif "--no-id" not in args:
            response["id"] = request.get("id")
        print(json.dumps(response), flush=True)


if __name__ == "__main__":
    main()
