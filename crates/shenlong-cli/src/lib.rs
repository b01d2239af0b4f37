//! The parts of the `shenlong` command that are worth testing from outside: the web
//! editor's server, the MCP server, and the editing session they share.

pub mod mcp;
pub mod server;
pub mod session;
pub mod terminal;
