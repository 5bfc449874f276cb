// How long report.html takes to be ready in headless Chromium (software
// WebGL), from navigation to the page's `data-ready`, three times, and
// whether the console saw an error. Not part of the build or the tests:
//
//   cargo run --release -- run examples/kitchen_wheelchair.reach --out /tmp/kw
//   npm install --prefix /tmp/pw playwright-core@1
//   NODE_PATH=/tmp/pw/node_modules node examples/bench_page.mjs /tmp/kw/report.html
//
// (Chromium at /usr/bin/chromium, or set CHROMIUM.)
import { createRequire } from "node:module";
import { statSync } from "node:fs";
import { resolve } from "node:path";

const require = createRequire(import.meta.url);
const { chromium } = require("playwright-core");
const file = resolve(process.argv[2]);
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
  args: ["--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
    "--disable-quic", "--disable-background-networking", "--disable-component-update",
    "--disable-sync"],
});
const page = await browser.newPage({ viewport: { width: 1400, height: 900 } });
const errors = [];
page.on("console", (m) => { if (m.type() === "error") errors.push(m.text()); });
page.on("pageerror", (e) => errors.push(String(e)));
console.log(`${file}: ${(statSync(file).size / 1e6).toFixed(2)} MB`);
for (let run = 1; run <= 3; run++) {
  const start = Date.now();
  await page.goto(`file://${file}`);
  await page.waitForSelector("body[data-ready]", { timeout: 20000 });
  console.log(`run ${run}: ready in ${Date.now() - start} ms`);
}
console.log(`console errors: ${errors.length ? errors.join("; ") : "none"}`);
await browser.close();
