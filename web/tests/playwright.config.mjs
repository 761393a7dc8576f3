// Playwright configuration of the studio's browser tests: the system Chromium headless
// (WebGL through SwiftShader), the page served by `shitsukan studio` (run.sh starts it
// and passes its address in STUDIO_URL).
import { defineConfig } from '@playwright/test';

export default defineConfig({
  testDir: '.',
  testMatch: /.*\.spec\.mjs$/,
  timeout: 60000,
  workers: 1,
  reporter: [['list']],
  outputDir: process.env.STUDIO_TEST_OUT || 'test-results',
  use: {
    baseURL: process.env.STUDIO_URL,
    viewport: { width: 1280, height: 800 },
    acceptDownloads: true,
    launchOptions: {
      executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
      args: ['--no-sandbox', '--enable-unsafe-swiftshader'],
    },
  },
});
