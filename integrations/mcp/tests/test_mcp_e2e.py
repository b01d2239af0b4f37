"""End to end: the official MCP Python SDK (`mcp` on PyPI) as the client of `shenlong mcp`.

    python3.11 -m venv /tmp/mcp && /tmp/mcp/bin/pip install "mcp>=2,<3"
    SHENLONG_BIN=target/debug/shenlong /tmp/mcp/bin/python -m unittest discover -s integrations/mcp/tests -v
"""

from __future__ import annotations

import base64
import json
import os
import tempfile
import unittest

try:
    from mcp import ClientSession, StdioServerParameters
    from mcp.client.stdio import stdio_client
except ImportError:  # pragma: no cover - reported by the runner
    raise unittest.SkipTest("the mcp package is not installed (pip install 'mcp>=2,<3')")


def binary() -> str:
    path = os.environ.get("SHENLONG_BIN")
    if not path:
        raise unittest.SkipTest("SHENLONG_BIN is not set to the shenlong binary")
    return os.path.abspath(path)


def structured(result):
    assert not result.is_error, result.content
    return result.structured_content


def by_name(listing, name):
    return next(o for o in listing["objects"] if o["name"] == name)


class McpEndToEnd(unittest.IsolatedAsyncioTestCase):
    async def test_an_assistant_session(self):
        with tempfile.TemporaryDirectory() as tmp:
            save = os.path.join(tmp, "edited.json")
            params = StdioServerParameters(
                command=binary(), args=["mcp", "example:workshop", "--save", save]
            )
            async with stdio_client(params) as (read, write):
                async with ClientSession(read, write) as session:
                    init = await session.initialize()
                    self.assertIsNotNone(init.capabilities.tools)

                    tools = {t.name: t for t in (await session.list_tools()).tools}
                    for name in ("list_objects", "edit", "apply", "undo", "redo", "history", "render", "save", "export"):
                        self.assertIn(name, tools)
                    self.assertIn("objects", tools["list_objects"].output_schema["properties"])
                    self.assertIn("T(", tools["apply"].description)

                    listing = structured(await session.call_tool("list_objects", {}))
                    table_top = by_name(listing, "tool table")["world_box"]["max"][1]

                    report = structured(
                        await session.call_tool(
                            "edit", {"instruction": "put the 'orange bottle' on top of the 'tool table'"}
                        )
                    )
                    self.assertEqual(report["understood"]["bindings"][0]["object"], "orange bottle")
                    self.assertEqual([m["object"] for m in report["moved"]], ["orange bottle"])
                    self.assertNotIn("report", report, "the whole report only when asked for")
                    listing = structured(await session.call_tool("list_objects", {}))
                    bottle = by_name(listing, "orange bottle")
                    self.assertAlmostEqual(bottle["world_box"]["min"][1], table_top, places=9)
                    self.assertEqual(bottle["rests_on"], "tool table")

                    refused = await session.call_tool("edit", {"instruction": "move the 'grand piano' left"})
                    self.assertTrue(refused.is_error)
                    self.assertIn("grand piano", refused.content[0].text)
                    self.assertEqual(refused.structured_content["kind"], "not_understood")

                    applied = structured(
                        await session.call_tool(
                            "apply",
                            {"object": "workbench", "expression": "T(((X2.max | e2) - (X1.min | e2)) * e2 + 3*e1)",
                             "bind": {"X2": "tool table"}},
                        )
                    )
                    self.assertIsNotNone(applied["history_id"])
                    listing = structured(await session.call_tool("list_objects", {}))
                    bench = by_name(listing, "workbench")
                    self.assertAlmostEqual(bench["world_box"]["min"][1], table_top, places=9)

                    hostile = await session.call_tool(
                        "apply", {"object": "workbench", "expression": "__import__('os').system('rm -rf /')"}
                    )
                    self.assertTrue(hostile.is_error)

                    structured(await session.call_tool("undo", {}))
                    listing = structured(await session.call_tool("list_objects", {}))
                    self.assertAlmostEqual(by_name(listing, "workbench")["world_box"]["min"][1], 0.0, places=9)

                    render = await session.call_tool("render", {"before": True})
                    self.assertFalse(render.is_error)
                    image = render.content[0]
                    self.assertEqual(image.mime_type, "image/png")
                    self.assertEqual(base64.b64decode(image.data)[:8], b"\x89PNG\r\n\x1a\n")

                    self.assertFalse(os.path.exists(save))
                    structured(await session.call_tool("save", {}))
                    with open(save, encoding="utf-8") as f:
                        written = json.load(f)
                    bottle = next(o for o in written["objects"] if o["name"] == "orange bottle")
                    self.assertAlmostEqual(bottle["position"][1], table_top, places=9)

                    resource = await session.read_resource("scene://current")
                    self.assertEqual(json.loads(resource.contents[0].text)["name"], "workshop")


if __name__ == "__main__":
    unittest.main()
