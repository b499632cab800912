// ESLint (flat config) for every JS file of the tree: the package (wasm/), the demo (web/), tests,
// benchmarks and scripts. Layout is Prettier's (.prettierrc.json); scripts/lint.sh runs both.
import js from '@eslint/js';
import globals from 'globals';

export default [
  {
    ignores: [
      'build*/**',
      'dist/**',
      'web/dist/**',
      'web/public/api/**',
      'docs/api/**',
      'tests/artifacts/**',
      '**/node_modules/**',
    ],
  },
  js.configs.recommended,
  {
    files: ['**/*.js', '**/*.mjs'],
    languageOptions: {
      ecmaVersion: 2022,
      sourceType: 'module',
      // The package runs in browsers, workers and Node; the demo in browsers and workers.
      globals: { ...globals.browser, ...globals.worker },
    },
    rules: {
      'no-unused-vars': ['error', { argsIgnorePattern: '^_', varsIgnorePattern: '^_', caughtErrors: 'none' }],
      eqeqeq: ['error', 'smart'],
      'no-var': 'error',
      'prefer-const': 'error',
    },
  },
  {
    // Node programs; the e2e tests also hand functions to the page (browser globals above).
    files: ['tests/**', 'bench/**', 'scripts/**', 'examples/**/*.mjs', 'eslint.config.js'],
    languageOptions: { globals: { ...globals.node, ...globals.browser } },
  },
  {
    // The package's Node path (reading the .wasm with fs) checks for `process` before using it.
    files: ['wasm/**'],
    languageOptions: { globals: { ...globals.browser, ...globals.worker, process: 'readonly' } },
  },
];
